#include "mesh/sizing_field.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/vertex_normals.hpp"

namespace cortex {
namespace {

constexpr int kCurvatureSmoothingPasses = 1;

// Area-weighted averages of a per-vertex field over each vertex and its 1-ring.
void smoothOverRings(const SurfaceMesh& m, const std::vector<double>& area, std::vector<double>& field) {
  for (int pass = 0; pass < kCurvatureSmoothingPasses; ++pass) {
    std::vector<double> smoothed(m.numVertices());
    for (Index v = 0; v < m.numVertices(); ++v) {
      double sum = area[v] * field[v], weight = area[v];
      for (const Index h : m.outgoingHalfedges(v)) {
        sum += area[m.tip(h)] * field[m.tip(h)];
        weight += area[m.tip(h)];
      }
      smoothed[v] = weight > 0 ? sum / weight : field[v];
    }
    field.swap(smoothed);
  }
}

// Largest principal curvature k_max = |H| + sqrt(max(H^2 - K, 0)) per vertex, with H the
// mean of the normal curvatures along the 1-ring edges, (n_v - n_u).(x_v - x_u) / |x_v -
// x_u|^2, and K the angle defect per area, both averaged over 1-rings. Area-weighted
// normals are robust on poor triangles, where the cotan curvature of a raw
// marching-tetrahedra mesh reads ten times the true value.
std::vector<double> largestPrincipalCurvature(const SurfaceMesh& m) {
  const std::vector<Vec3> normals = vertexNormals(m);
  const auto& p = m.positions();
  std::vector<double> mean(m.numVertices(), 0.0), gaussian(m.numVertices()), area(m.numVertices());
  for (Index v = 0; v < m.numVertices(); ++v) {
    const VertexCurvature k = vertexCurvature(m, v);
    area[v] = k.area;
    gaussian[v] = k.gaussian;
    for (const Index h : m.outgoingHalfedges(v)) {
      const Vec3 d = p[v] - p[m.tip(h)];
      if (d.squaredNorm() > 0) mean[v] += (normals[v] - normals[m.tip(h)]).dot(d) / d.squaredNorm() / m.valence(v);
    }
  }
  smoothOverRings(m, area, mean);
  smoothOverRings(m, area, gaussian);
  std::vector<double> k_max(m.numVertices());
  for (Index v = 0; v < m.numVertices(); ++v)
    k_max[v] = std::abs(mean[v]) + std::sqrt(std::max(mean[v] * mean[v] - gaussian[v], 0.0));
  return k_max;
}

}  // namespace

double targetEdgeLength(double k, const SizingParameters& s) {
  const double eps = s.tolerance;
  const double squared = k > 0 ? 6.0 * eps / k - 3.0 * eps * eps : s.flat_size * s.flat_size;
  const double length = squared > 0 ? std::sqrt(squared) : 0.0;
  return std::clamp(std::min(length, s.flat_size), s.min_size, s.max_size);
}

std::vector<double> sizingField(const SurfaceMesh& m, const SizingParameters& s) {
  const std::vector<double> k_max = largestPrincipalCurvature(m);
  std::vector<double> target(m.numVertices());
  for (Index v = 0; v < m.numVertices(); ++v) target[v] = targetEdgeLength(k_max[v], s);
  // Boundary vertices have no reliable curvature: take the finest interior neighbour.
  for (Index v = 0; v < m.numVertices(); ++v) {
    if (!m.isBoundaryVertex(v)) continue;
    for (const Index h : m.outgoingHalfedges(v)) {
      if (!m.isBoundaryVertex(m.tip(h))) target[v] = std::min(target[v], target[m.tip(h)]);
    }
  }
  const auto& p = m.positions();
  for (int sweep = 0; sweep < 3; ++sweep)
    for (Index v = 0; v < m.numVertices(); ++v) {
      for (const Index h : m.outgoingHalfedges(v)) {
        const Index u = m.tip(h);
        target[v] = std::min(target[v], target[u] + s.gradation * (p[v] - p[u]).norm());
      }
    }
  return target;
}

}  // namespace cortex
