// Flat rectangular membrane patches (tension and tether tests, periodic-like sheets).
#pragma once

#include "mesh/triangle_soup.hpp"

namespace cortex {

// Rectangle [cx - Lx/2, cx + Lx/2] x [cy - Ly/2, cy + Ly/2] in the plane z = center.z,
// normals +z. Rows of near-equilateral triangles, spaced ~target_edge * sqrt(3)/2, odd rows
// shifted by half an edge; every row starts and ends on the rectangle's sides, so the
// boundary is straight and the area exactly Lx * Ly. Interior angles are near 60 degrees
// and the half-width triangles at the left and right sides have a ~30 degree angle, as
// long as the sides are many edges long: rounding the counts up stretches the triangles
// of narrow patches (minimum angle 21.6 degrees for 101 x 1234 at edge 50).
TriangleSoup planarPatch(const Vec3& center, double Lx, double Ly, double target_edge);

}  // namespace cortex
