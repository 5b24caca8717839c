// Whether a point or a straight filament lies inside a closed membrane, for placing
// filaments at random inside a vesicle (`[[filaments]] inside`, thesis fig. 2.4a).
// Brute force over the triangles: placement asks a few thousand times, once per run.
#pragma once

#include "core/types.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex {

// The winding number of a closed, outward-oriented mesh about p: 1 inside, 0 outside
// (the sum of the triangles' signed solid angles over 4π, Van Oosterom and Strackee 1983),
// robust where a ray cast would graze an edge or a vertex.
double windingNumber(const SurfaceMesh& mesh, const Vec3& p);

// Distance (nm) from p to the nearest triangle.
double distanceToMesh(const SurfaceMesh& mesh, const Vec3& p);

// The segment [a, b] inside the closed mesh, every point of it at least `margin` nm from
// it: points along it no more than margin apart are each that far from the mesh, so
// their balls of radius margin cover the segment and none of them meets the mesh, and
// the first is inside.
bool segmentInside(const SurfaceMesh& mesh, const Vec3& a, const Vec3& b, double margin);

}  // namespace cortex
