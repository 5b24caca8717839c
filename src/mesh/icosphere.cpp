#include "mesh/icosphere.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <fmt/format.h>

#include "core/error.hpp"

namespace cortex {
namespace {

constexpr int kMaxSubdivisions = 9;  // 2.6 M vertices; beyond that Index arithmetic is tight
constexpr int kMaxAutomaticSubdivisions = 7;

// Unit icosahedron: vertices (0, ±1, ±φ) and cyclic permutations, normalized.
TriangleSoup unitIcosahedron() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleSoup soup;
  soup.positions = {{-1, phi, 0}, {1, phi, 0},  {-1, -phi, 0}, {1, -phi, 0},
                    {0, -1, phi}, {0, 1, phi},  {0, -1, -phi}, {0, 1, -phi},
                    {phi, 0, -1}, {phi, 0, 1},  {-phi, 0, -1}, {-phi, 0, 1}};
  for (Vec3& p : soup.positions) p.normalize();
  soup.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  return soup;
}

// Splits every triangle into 4; the midpoint of an edge is created once and reused by
// the triangle on its other side, keeping the mesh closed.
void subdivideOnUnitSphere(TriangleSoup& soup) {
  std::unordered_map<std::int64_t, Index> midpoint_of;
  auto midpoint = [&](Index a, Index b) {
    const std::int64_t key = std::int64_t(std::min(a, b)) << 32 | std::int64_t(std::max(a, b));
    const auto [it, inserted] = midpoint_of.try_emplace(key, Index(soup.positions.size()));
    if (inserted) soup.positions.push_back((soup.positions[a] + soup.positions[b]).normalized());
    return it->second;
  };
  std::vector<Tri> finer;
  finer.reserve(4 * soup.triangles.size());
  for (const Tri& t : soup.triangles) {
    const Index ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    finer.push_back({t[0], ab, ca});
    finer.push_back({t[1], bc, ab});
    finer.push_back({t[2], ca, bc});
    finer.push_back({ab, bc, ca});
  }
  soup.triangles = std::move(finer);
}

// Every edge belongs to two triangles, so the mean over triangle sides is the mean edge.
double meanEdgeLength(const TriangleSoup& soup) {
  double sum = 0.0;
  for (const Tri& t : soup.triangles) {
    for (int k = 0; k < 3; ++k) {
      sum += (soup.positions[t[k]] - soup.positions[t[(k + 1) % 3]]).norm();
    }
  }
  return sum / (3.0 * double(soup.triangles.size()));
}

void requirePositive(const char* what, double value) {
  if (!(value > 0.0)) {
    throw InputError(fmt::format("icosphere: {} must be > 0 (got {})", what, value));
  }
}

}  // namespace

TriangleSoup icosphere(const Vec3& center, double radius, int subdivisions) {
  requirePositive("radius", radius);
  if (subdivisions < 0 || subdivisions > kMaxSubdivisions) {
    throw InputError(fmt::format("icosphere: subdivisions must be in [0, {}] (got {})",
                                 kMaxSubdivisions, subdivisions));
  }
  TriangleSoup soup = unitIcosahedron();
  for (int level = 0; level < subdivisions; ++level) subdivideOnUnitSphere(soup);
  for (Vec3& p : soup.positions) p = center + radius * p;
  return soup;
}

int icosphereSubdivisionsFor(double radius, double target_edge) {
  requirePositive("radius", radius);
  requirePositive("target edge", target_edge);
  // Levels are built incrementally, so finding level n costs about as much as building it.
  TriangleSoup unit = unitIcosahedron();
  for (int level = 0; level < kMaxAutomaticSubdivisions; ++level) {
    if (radius * meanEdgeLength(unit) <= target_edge) return level;
    subdivideOnUnitSphere(unit);
  }
  return kMaxAutomaticSubdivisions;
}

}  // namespace cortex
