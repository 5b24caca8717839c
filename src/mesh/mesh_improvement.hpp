// Quality improvement of a mesh without changing the surface it represents: edge flips
// that bring valences towards 6 (4 on boundaries), and tangential smoothing followed by
// projection back onto the surface (Botsch & Kobbelt 2004, without splits/collapses).
//
// Why: the curvature estimators of thesis eqs. 2.8-2.9 converge only on meshes of
// regular valence; on raw marching-tetrahedra meshes the sphere's bending energy stays
// ~2.5% above 8 pi kappa however fine the mesh (docs/membrane.md).
#pragma once

#include <functional>

#include "mesh/surface_mesh.hpp"

namespace cortex {

using SurfaceProjector = std::function<Vec3(const Vec3&)>;
// Told of every flip done: edge a-b of triangles (a,b,c), (b,a,d) became c-d.
using FlipObserver = std::function<void(Index a, Index b, Index c, Index d)>;

// One sweep of valence-improving flips over all interior edges. Flips that would fold
// a triangle over (normals of the new pair disagreeing with the old pair) are refused,
// and so, with keep_delaunay, are flips whose new edge would not be Delaunay (so that
// valence and Delaunay sweeps do not undo each other). Returns the number of flips.
Index equalizeValences(SurfaceMesh& mesh, bool keep_delaunay = false, const FlipObserver& on_flip = {});

// One sweep of Delaunay flips: an interior edge whose two opposite angles sum to more
// than pi is flipped (which raises the smallest angle of the pair), unless the flip
// would fold the surface. Returns the number of flips.
Index flipToDelaunay(SurfaceMesh& mesh, const FlipObserver& on_flip = {});

// Moves every non-boundary vertex towards the centroid of its neighbours within its
// tangent plane, then onto the surface. `step` in (0, 1] is the fraction moved.
void smoothTangentially(SurfaceMesh& mesh, const SurfaceProjector& project, double step);

// Alternates the two until no flip is left or `rounds` is reached.
void improveMesh(SurfaceMesh& mesh, const SurfaceProjector& project, int rounds);

}  // namespace cortex
