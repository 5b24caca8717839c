// Copies spread over a mesh's dual cells, and how far they are from a uniform density:
// shared by the tests of the copy carrier and the lipid flow.
#pragma once

#include <random>
#include <vector>

#include "mesh/copy_carrier.hpp"

namespace cortex::testing {

inline constexpr auto everywhere = [](const Vec3&) { return true; };

// `total` copies dropped one by one on the cells (among those `where` accepts) with
// probability proportional to their areas.
template <class Where = decltype(everywhere)>
std::vector<int> dropCopiesByArea(const SurfaceMesh& m, long total, unsigned seed, Where where = everywhere) {
  std::vector<double> weight = dualCellAreas(m);
  for (Index v = 0; v < m.numVertices(); ++v)
    if (!where(m.positions()[v])) weight[v] = 0.0;
  std::mt19937 rng(seed);
  std::discrete_distribution<Index> cell(weight.begin(), weight.end());
  std::vector<int> copies(m.numVertices(), 0);
  for (long k = 0; k < total; ++k) ++copies[cell(rng)];
  return copies;
}

// Pearson chi-square per cell of the copies against a density uniform over the cells
// `where` accepts. For copies spread by area it is 1 ± sqrt(2/cells).
template <class Where = decltype(everywhere)>
double chiSquarePerCell(const SurfaceMesh& m, const std::vector<int>& copies, Where where = everywhere) {
  const std::vector<double> area = dualCellAreas(m);
  double region = 0.0;
  long total = 0;
  Index cells = 0;
  for (Index v = 0; v < m.numVertices(); ++v)
    if (where(m.positions()[v])) region += area[v], total += copies[v], ++cells;
  double chi2 = 0.0;
  for (Index v = 0; v < m.numVertices(); ++v) {
    if (!where(m.positions()[v])) continue;
    const double expected = total * area[v] / region;
    chi2 += (copies[v] - expected) * (copies[v] - expected) / expected;
  }
  return chi2 / cells;
}

}  // namespace cortex::testing
