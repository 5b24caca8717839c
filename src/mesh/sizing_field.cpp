#include "mesh/sizing_field.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/vertex_normals.hpp"

namespace cortex {
namespace {
constexpr int kCurvatureSmoothingPasses = 2;
}  // namespace

double targetEdgeLength(double k, const SizingParameters& s) {
  const double eps = s.tolerance;
  const double squared = k > 0 ? 6.0 * eps / k - 3.0 * eps * eps : s.flat_size * s.flat_size;
  const double length = squared > 0 ? std::sqrt(squared) : 0.0;
  return std::clamp(std::min(length, s.flat_size), s.min_size, s.max_size);
}

std::vector<double> sizingField(const SurfaceMesh& m, const SizingParameters& s) {
  // The largest principal curvature is estimated from how fast the vertex normal turns
  // along each edge, |n_u - n_v| / |x_u - x_v| (exactly 1/R on a sphere, 1/r across a
  // cylinder): area-weighted normals are robust on poor triangles, where the cotan
  // curvature of a raw marching-tetrahedra mesh reads ten times the true value. The
  // estimate is then averaged over 1-rings.
  const std::vector<Vec3> normals = vertexNormals(m);
  std::vector<double> curvature(m.numVertices(), 0.0), area(m.numVertices());
  for (Index v = 0; v < m.numVertices(); ++v) {
    area[v] = vertexCurvature(m, v).area;
    Index h = m.outgoing(v);
    do {
      const Index u = m.tip(h);
      const double length = (m.positions()[u] - m.positions()[v]).norm();
      if (length > 0) curvature[v] += (normals[u] - normals[v]).norm() / length / m.valence(v);
      h = m.rotate(h);
    } while (h != m.outgoing(v));
  }
  for (int pass = 0; pass < kCurvatureSmoothingPasses; ++pass) {
    std::vector<double> smoothed(m.numVertices());
    for (Index v = 0; v < m.numVertices(); ++v) {
      double sum = area[v] * curvature[v], weight = area[v];
      Index h = m.outgoing(v);
      do {
        sum += area[m.tip(h)] * curvature[m.tip(h)];
        weight += area[m.tip(h)];
        h = m.rotate(h);
      } while (h != m.outgoing(v));
      smoothed[v] = weight > 0 ? sum / weight : curvature[v];
    }
    curvature.swap(smoothed);
  }
  std::vector<double> target(m.numVertices());
  for (Index v = 0; v < m.numVertices(); ++v) target[v] = targetEdgeLength(curvature[v], s);
  // Boundary vertices have no reliable curvature: take the finest neighbour.
  for (Index v = 0; v < m.numVertices(); ++v) {
    if (!m.isBoundaryVertex(v)) continue;
    Index h = m.outgoing(v);
    do {
      if (!m.isBoundaryVertex(m.tip(h))) target[v] = std::min(target[v], target[m.tip(h)]);
      h = m.rotate(h);
    } while (h != m.outgoing(v));
  }
  const auto& p = m.positions();
  for (int sweep = 0; sweep < 3; ++sweep)
    for (Index v = 0; v < m.numVertices(); ++v) {
      Index h = m.outgoing(v);
      do {
        const Index u = m.tip(h);
        target[v] = std::min(target[v], target[u] + s.gradation * (p[v] - p[u]).norm());
        h = m.rotate(h);
      } while (h != m.outgoing(v));
    }
  return target;
}

}  // namespace cortex
