// Binding from a compartment onto the surface subvolumes it holds (an aggregated
// reaction, chemistry.md): each binding lands on subvolume j with probability
// c_j / Σ c, c_j = rate factor × area, also after the factors change between advances
// (the engines cache the weights: a stale cache would keep binding where a factor
// became 0). Both engines; fixed seeds.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "chem/chemistry_engine.hpp"
#include "chem/reaction_network.hpp"
#include "chem_models.hpp"

namespace cortex {
namespace {

constexpr std::array<double, 3> kAreas{100.0, 200.0, 300.0};  // nm^2

// One compartment holding a three-subvolume surface; C binds (C -> M) and nothing moves.
struct BindingSurface {
  ChemistryModel model;
  SubvolumeGraph surface;

  BindingSurface() {
    model.volumes = SubvolumeGraph{};
    model.volumes.size = {1.0e9};  // nm^3
    model.volumes.start = {0, 0};
    model.surfaces = {"membrane"};
    model.species = {{"C", 0.0, -1}, {"M", 0.0, 0}};
    model.addReactions("test", {parseReaction("C -> M", 1.0, model.species)});
    surface.size.assign(kAreas.begin(), kAreas.end());
    surface.start = {0, 0, 0, 0};
  }
};

std::array<int, 3> bound(const ChemistryEngine& e) {
  const Index first = e.regionStart(1);
  return {e.copies(first, 1), e.copies(first + 1, 1), e.copies(first + 2, 1)};
}

// Counts on the open subvolumes against a multinomial split ∝ weight: each within 5
// binomial standard errors; a closed one (weight 0) gets none at all.
void expectSplit(const std::array<int, 3>& counts, const std::array<double, 3>& weight) {
  const double total = counts[0] + counts[1] + counts[2], sum = weight[0] + weight[1] + weight[2];
  ASSERT_GT(total, 1000.0);
  for (int j = 0; j < 3; ++j) {
    const double p = weight[j] / sum;
    if (p == 0.0) {
      EXPECT_EQ(counts[j], 0) << "subvolume " << j << " is closed";
      continue;
    }
    EXPECT_NEAR(counts[j] / total, p, 5.0 * std::sqrt(p * (1 - p) / total)) << "subvolume " << j;
  }
}

class BindingDraws : public ::testing::TestWithParam<EngineKind> {};

TEST_P(BindingDraws, LandWhereTheFactorsSayBeforeAndAfterTheyChange) {
  const BindingSurface sys;
  auto engine = makeChemistryEngine(GetParam(), sys.model, {200000, 0}, 17);
  engine->setSurface(0, sys.surface, {0, 0, 0}, std::vector<int>(6, 0));
  const RateFactors factors = engine->claimRateFactors(sys.model.ranges.front());
  const Index first = engine->regionStart(1);
  const std::array<double, 3> before{1.0, 0.0, 1.0}, after{0.0, 2.0, 1.0};
  for (int j = 0; j < 3; ++j) factors.set(0, first + j, before[j]);
  // Binding at 1 nm/s × [C] × area: ~0.08 /s per nm^2 of open area, ~30 per second here.
  const double rate = 200000 / 1.0e9;  // copies per nm^3
  const double open = kAreas[0] + kAreas[2];
  const double t1 = 3000.0 / (rate * open);
  engine->advance(t1);
  const std::array<int, 3> first_counts = bound(*engine);
  expectSplit(first_counts, {kAreas[0] * before[0], kAreas[1] * before[1], kAreas[2] * before[2]});

  for (int j = 0; j < 3; ++j) factors.set(0, first + j, after[j]);
  engine->advance(t1 + 3000.0 / (rate * (2.0 * kAreas[1] + kAreas[2])));
  const std::array<int, 3> now = bound(*engine);
  expectSplit({now[0] - first_counts[0], now[1] - first_counts[1], now[2] - first_counts[2]},
              {kAreas[0] * after[0], kAreas[1] * after[1], kAreas[2] * after[2]});
}

INSTANTIATE_TEST_SUITE_P(Engines, BindingDraws,
                         ::testing::Values(EngineKind::kNextSubvolume, EngineKind::kDirect),
                         [](const auto& info) { return std::string(chemtest::engineName(info.param)); });

}  // namespace
}  // namespace cortex
