#include "mesh/surface_smoothing.hpp"

#include <numeric>
#include <vector>

#include <Eigen/Geometry>

namespace cortex {
namespace {

// Vertex -> incident triangles, as offsets into one flat list (compressed rows).
struct Incidence {
  std::vector<Index> offset, faces;
  explicit Incidence(const TriangleSoup& soup) : offset(soup.positions.size() + 1, 0) {
    for (const Tri& t : soup.triangles) {
      for (Index v : t) ++offset[v + 1];
    }
    std::partial_sum(offset.begin(), offset.end(), offset.begin());
    faces.resize(offset.back());
    std::vector<Index> fill(offset.begin(), offset.end() - 1);
    for (Index f = 0; f < Index(soup.triangles.size()); ++f) {
      for (Index v : soup.triangles[f]) faces[fill[v]++] = f;
    }
  }
};

}  // namespace

void smoothOnSurface(TriangleSoup& soup, const ImplicitSurface& surface, double edge,
                     int iterations) {
  const Incidence ring(soup);
  std::vector<Vec3>& x = soup.positions;
  std::vector<Vec3> next(x.size());
  const double negligible_area = 1e-12 * edge * edge;
  for (int it = 0; it < iterations; ++it) {
    for (Index v = 0; v < Index(x.size()); ++v) {
      Vec3 weighted = Vec3::Zero();
      double area = 0.0;
      for (Index k = ring.offset[v]; k < ring.offset[v + 1]; ++k) {
        const Tri& t = soup.triangles[ring.faces[k]];
        const double a = 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
        weighted += a * (x[t[0]] + x[t[1]] + x[t[2]]) / 3.0;
        area += a;
      }
      next[v] = x[v];
      if (!(area > negligible_area)) continue;  // degenerate ring: no meaningful centroid
      Vec3 move = weighted / area - x[v];
      const Vec3 normal = surface.gradientAt(x[v]).normalized();
      if (normal.allFinite()) move -= normal.dot(move) * normal;
      const Vec3 moved = surface.project(x[v] + move);
      if (moved.allFinite()) next[v] = moved;
    }
    x.swap(next);
  }
}

std::size_t countInvertedTriangles(const TriangleSoup& soup, const ImplicitSurface& surface) {
  std::size_t inverted = 0;
  for (const Tri& t : soup.triangles) {
    const Vec3& a = soup.positions[t[0]];
    const Vec3& b = soup.positions[t[1]];
    const Vec3& c = soup.positions[t[2]];
    if ((b - a).cross(c - a).dot(surface.gradientAt((a + b + c) / 3.0)) < 0.0) ++inverted;
  }
  return inverted;
}

}  // namespace cortex
