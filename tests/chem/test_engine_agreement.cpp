// The next-subvolume method against the direct method on a random network of 50
// coupled reactions with diffusion (issue 4 acceptance). Stochastic test, fixed seeds.
#include <gtest/gtest.h>

#include <cmath>

#include "chem_models.hpp"
#include "chem_statistics.hpp"

namespace cortex {
namespace {

struct Observed {
  std::vector<int> total0;  // copies of X0 summed over both compartments
  std::vector<int> local1;  // copies of X1 in compartment 0
  std::vector<int> local2;  // copies of X2 in compartment 1
};

Observed run(EngineKind kind, const ChemistryModel& m, std::uint64_t seed) {
  auto engine = makeChemistryEngine(kind, m, std::vector<int>(m.volumes.count() * m.species.size(), 0), seed);
  engine->advance(20.0);
  Observed o;
  for (int i = 0; i < 3000; ++i) {
    engine->advance(engine->time() + 4.0);
    o.total0.push_back(chemtest::total(*engine, m.volumes.count(), 0));
    o.local1.push_back(engine->copies(0, 1));
    o.local2.push_back(engine->copies(1, 2));
  }
  return o;
}

// Five species in two compartments (hops at 1/s per copy), 50 reactions of orders 0-2:
// stationary marginals must be statistically indistinguishable. Samples 4 s apart are
// independent (every species decays at >= 0.5/s; the measured lag-1 autocorrelation is
// checked below 0.1, 5 standard errors of an estimate from 3000 samples). Tolerances:
// two-sample chi-square p > 1e-4, means within 5 combined standard errors.
TEST(EngineAgreement, NextSubvolumeMatchesDirectMethodOnFiftyReactions) {
  CompartmentGrid grid;
  grid.shape = {2, 1, 1};
  const ChemistryModel m = chemtest::randomNetwork(5, 50, 2024, grid, grid.size * grid.size);
  const Observed nsm = run(EngineKind::kNextSubvolume, m, 31);
  const Observed direct = run(EngineKind::kDirect, m, 32);

  const std::vector<std::pair<const char*, std::pair<const std::vector<int>*, const std::vector<int>*>>> series = {
      {"X0 total", {&nsm.total0, &direct.total0}},
      {"X1 in compartment 0", {&nsm.local1, &direct.local1}},
      {"X2 in compartment 1", {&nsm.local2, &direct.local2}}};
  for (const auto& [label, pair] : series) {
    const auto& [a, b] = pair;
    EXPECT_LT(std::abs(chemtest::lagOneCorrelation(*a)), 0.1) << label;
    EXPECT_LT(std::abs(chemtest::lagOneCorrelation(*b)), 0.1) << label;
    const chemtest::Moments ma = chemtest::moments(*a), mb = chemtest::moments(*b);
    EXPECT_GT(ma.mean, 2.0) << label << ": the network should keep copies around";
    EXPECT_NEAR(ma.mean, mb.mean, 5.0 * std::hypot(ma.standardError, mb.standardError)) << label;
    const chemtest::ChiSquare test = chemtest::twoSample(*a, *b);
    EXPECT_GT(test.p, 1e-4) << label << ": chi2 " << test.statistic << " dof " << test.dof;
  }
}

}  // namespace
}  // namespace cortex
