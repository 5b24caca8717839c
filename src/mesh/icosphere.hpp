// Geodesic spheres: the regular meshes used by curvature tests and spherical cells.
#pragma once

#include "mesh/triangle_soup.hpp"

namespace cortex {

// Icosahedron subdivided `subdivisions` times (each triangle into 4, midpoints shared)
// with every vertex on the sphere: 10 * 4^n + 2 vertices (12, 42, 162, 642, 2562, ...).
// Outward oriented. subdivisions must be in [0, 9].
TriangleSoup icosphere(const Vec3& center, double radius, int subdivisions);

// Smallest subdivision level whose mean edge length is <= target_edge, capped at 7
// (163,842 vertices).
int icosphereSubdivisionsFor(double radius, double target_edge);

}  // namespace cortex
