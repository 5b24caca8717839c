// Point and segment queries against one triangle, for the membrane–filament contact: the
// distance that decides which bead–triangle pairs interact, and the test that a filament
// segment does not pass through the membrane.
#pragma once

#include <array>

#include "core/types.hpp"

namespace cortex {

// The point of triangle (a, b, c) nearest to p, point = Σ weight_i vertex_i with weights
// ≥ 0 summing to 1 (Ericson, Real-Time Collision Detection, 5.1.5: by the Voronoi region
// of p). A degenerate triangle gives a point of its hull. The distance |p − point| to a
// triangle (a convex set) has the continuous gradient (p − point)/|p − point| in p and
// −weight_i (p − point)/|p − point| in vertex i (envelope theorem) away from it.
struct TrianglePoint {
  Vec3 point;
  std::array<double, 3> weight;
};
TrianglePoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// Whether the closed segment [p, q] meets triangle (a, b, c), touching included: signed
// volumes (orientation tests) of the segment against the triangle's edges, so a segment
// through an edge or a vertex shared by two triangles is reported by at least one.
bool segmentMeetsTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace cortex
