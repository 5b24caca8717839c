// Two single copies on a surface (species 1 and 2 of a model whose species 0 is the 3D
// one): where they sit, sampled over time, and the fit of their joint positions against
// a known stationary distribution. The crowding and cross-interaction tests both use it.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "chem/chem_statistics.hpp"
#include "chem/chemistry_engine.hpp"

namespace cortex::chemtest {

// `count` samples `spacing` s apart of the surface subvolumes (of n, region-local)
// holding the copy of species 1 (p) and of species 2 (q), as p·n + q. A copy missing is a
// test failure (the samples end there).
inline std::vector<int> sampleTwoCopies(ChemistryEngine& engine, Index n, int count, double spacing) {
  std::vector<int> samples;
  for (int k = 0; k < count; ++k) {
    engine.advance(engine.time() + spacing);
    Index p = -1, q = -1;
    for (Index v = 0; v < n; ++v) {
      if (engine.copies(engine.regionStart(1) + v, 1) == 1) p = v;
      if (engine.copies(engine.regionStart(1) + v, 2) == 1) q = v;
    }
    if (p < 0 || q < 0) {
      ADD_FAILURE() << "a copy was lost";
      return samples;
    }
    samples.push_back(static_cast<int>(p * n + q));
  }
  return samples;
}

// Pearson's test of such samples against stationary weights w(p, q) ≥ 0 (normalized here).
inline ChiSquare fitTwoCopies(const std::vector<int>& samples, Index n,
                              const std::function<double(Index, Index)>& weight) {
  std::vector<double> prob(static_cast<std::size_t>(n * n), 0.0);
  double z = 0.0;
  for (Index p = 0; p < n; ++p)
    for (Index q = 0; q < n; ++q) z += prob[p * n + q] = weight(p, q);
  return goodnessOfFit(samples, [&](int a) { return a < static_cast<int>(prob.size()) ? prob[a] / z : 0.0; });
}

}  // namespace cortex::chemtest
