// Triangle meshes of implicit surfaces: raw marching tetrahedra, and a smoothed version
// ready to simulate.
#pragma once

#include "mesh/implicit_shapes.hpp"
#include "mesh/triangle_soup.hpp"

namespace cortex {

// Closed, outward-oriented 2-manifold (for a surface inside its box) from a regular grid
// of the given spacing over surface's box padded by 2 cells. Raw quality: minimum angles
// near 0°, so use meshImplicitSurface() for anything that will be simulated.
TriangleSoup marchingTetrahedra(const ImplicitSurface& surface, double spacing);

// Marching tetrahedra with a spacing chosen so the mean edge is close to target_edge,
// then valence-3 vertices removed and tangential smoothing with projection back onto
// the surface (connectivity otherwise unchanged). Deterministic.
TriangleSoup meshImplicitSurface(const ImplicitSurface& surface, double target_edge);

}  // namespace cortex
