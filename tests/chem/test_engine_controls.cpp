// What the rest of the program does to an engine between advances: rate factors,
// setting copies, checkpoints; and that a run is a pure function of inputs and seed.
// Both engines. Statistical checks use fixed seeds and 5-sigma tolerances.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "chem_models.hpp"
#include "core/error.hpp"

namespace cortex {
namespace {

class Controls : public ::testing::TestWithParam<EngineKind> {};

// -> A at 100 copies/s and A -> at 1/s in two compartments without diffusion.
ChemistryModel twoBirthDeathCompartments() {
  ChemistryModel m = chemtest::wellMixed({"A"}, {{"-> A", 0.0}, {"A ->", 1.0}});
  m.volumes = gridGraph(CompartmentGrid{500.0, {2, 1, 1}});
  m.reactions[0].rate = 100.0 / copiesPerMicromolar(m.volumes.size[0]);
  return m;
}

// Counts of an order-0 reaction over T are Poisson(a·T): factor 0 in one compartment
// silences it there exactly, factor 2 doubles its count within 5 sigma.
TEST_P(Controls, RateFactorsScaleOneReactionInOneCompartment) {
  const ChemistryModel m = twoBirthDeathCompartments();
  auto engine = makeChemistryEngine(GetParam(), m, {0, 0}, 41);
  const RateFactors factors = engine->claimRateFactors(m.ranges.front());
  factors.set(0, 1, 0.0);
  engine->advance(100.0);
  EXPECT_EQ(engine->copies(1, 0), 0);
  const double births = static_cast<double>(engine->reactionEvents()[0]);
  EXPECT_NEAR(births, 100.0 * 100.0, 5.0 * std::sqrt(100.0 * 100.0));

  factors.set(0, 1, 2.0);
  engine->advance(200.0);
  const double more = static_cast<double>(engine->reactionEvents()[0]) - births;
  EXPECT_NEAR(more, 300.0 * 100.0, 5.0 * std::sqrt(300.0 * 100.0));
  EXPECT_GT(engine->copies(1, 0), 0);
  EXPECT_EQ(engine->events(), engine->reactionEvents()[0] + engine->reactionEvents()[1]);
}

// Copies set between advances are what the next advance starts from: 1000 copies
// decaying at 1/s leave Binomial(1000, e^-1) after 1 s (5 sigma), and a diffusing
// species keeps its total.
TEST_P(Controls, SetCopiesBetweenAdvancesIsExact) {
  ChemistryModel m = chemtest::wellMixed({"A", "B"}, {{"A ->", 1.0}});
  m.volumes = gridGraph(CompartmentGrid{500.0, {3, 1, 1}});
  m.species[1].diffusion = 500.0 * 500.0;
  auto engine = makeChemistryEngine(GetParam(), m, std::vector<int>(6, 0), 42);
  engine->advance(1.0);
  EXPECT_EQ(engine->events(), 0);

  engine->setCopies(2, 0, 1000);
  engine->setCopies(0, 1, 77);
  EXPECT_EQ(engine->copies(2, 0), 1000);
  EXPECT_EQ(engine->copies(0, 1), 77);
  engine->advance(2.0);
  const double p = std::exp(-1.0);
  EXPECT_NEAR(engine->copies(2, 0), 1000 * p, 5.0 * std::sqrt(1000 * p * (1 - p)));
  EXPECT_EQ(chemtest::total(*engine, 3, 1), 77);
  EXPECT_GT(engine->diffusionEvents(), 0);

  engine->setCopies(2, 0, 0);
  const std::int64_t before = engine->reactionEvents()[0];
  engine->advance(3.0);
  EXPECT_EQ(engine->reactionEvents()[0], before);
}

ChemistryModel mixedModel() {
  CompartmentGrid grid;
  grid.shape = {3, 2, 2};
  return chemtest::randomNetwork(4, 30, 7, grid, 0.5 * grid.size * grid.size);
}

void expectSameState(const ChemistryEngine& a, const ChemistryEngine& b, const ChemistryModel& m) {
  for (Index c = 0; c < m.volumes.count(); ++c)
    for (Index s = 0; s < static_cast<Index>(m.species.size()); ++s)
      ASSERT_EQ(a.copies(c, s), b.copies(c, s)) << "compartment " << c << " species " << s;
  EXPECT_EQ(a.events(), b.events());
  EXPECT_EQ(a.reactionEvents(), b.reactionEvents());
  EXPECT_EQ(a.diffusionEvents(), b.diffusionEvents());
  EXPECT_EQ(a.random().counter(), b.random().counter());
  EXPECT_EQ(a.random().usedInBlock(), b.random().usedInBlock());
  EXPECT_EQ(a.time(), b.time());
}

TEST_P(Controls, SameSeedGivesIdenticalRuns) {
  const ChemistryModel m = mixedModel();
  const std::vector<int> initial(m.volumes.count() * m.species.size(), 3);
  auto a = makeChemistryEngine(GetParam(), m, initial, 43);
  auto b = makeChemistryEngine(GetParam(), m, initial, 43);
  auto other = makeChemistryEngine(GetParam(), m, initial, 44);
  for (double t : {0.5, 1.0, 3.0}) {
    a->advance(t);
    b->advance(t);
    other->advance(t);
  }
  EXPECT_GT(a->events(), 1000);
  expectSameState(*a, *b, m);
  EXPECT_NE(a->events(), other->events());
}

// A checkpoint stores copies, time, counters and the random stream (the rate factors are
// recomputed by their owners); an engine rebuilt from them continues bit for bit.
TEST_P(Controls, RestoredEngineContinuesIdentically) {
  const ChemistryModel m = mixedModel();
  const std::vector<int> initial(m.volumes.count() * m.species.size(), 5);
  auto original = makeChemistryEngine(GetParam(), m, initial, 45);
  original->claimRateFactors(m.ranges.front()).set(3, 2, 0.25);
  original->advance(1.5);

  // As a resumed run does: the same seed (from its config), the stored state, and the
  // factors set again by their owner.
  auto resumed = makeChemistryEngine(GetParam(), m, std::vector<int>(initial.size(), 0), 45);
  resumed->restore(original->state());
  resumed->claimRateFactors(m.ranges.front()).set(3, 2, 0.25);

  original->advance(4.0);
  resumed->advance(4.0);
  EXPECT_GT(original->events(), 1000);
  expectSameState(*original, *resumed, m);
}

TEST_P(Controls, CountersAddUpAndTimeReachesTheEnd) {
  const ChemistryModel m = mixedModel();
  auto engine = makeChemistryEngine(GetParam(), m, std::vector<int>(m.volumes.count() * m.species.size(), 2), 46);
  engine->advance(2.5);
  EXPECT_EQ(engine->time(), 2.5);
  std::int64_t sum = engine->diffusionEvents();
  for (std::int64_t n : engine->reactionEvents()) sum += n;
  EXPECT_EQ(sum, engine->events());
  EXPECT_GT(engine->diffusionEvents(), 0);
  engine->advance(2.5);  // no time, no events
  EXPECT_EQ(engine->events(), sum);
  EXPECT_THROW(engine->advance(1.0), std::invalid_argument);
}

TEST_P(Controls, RefusesBadArguments) {
  const ChemistryModel m = twoBirthDeathCompartments();
  EXPECT_THROW(makeChemistryEngine(GetParam(), m, {1}, 1), std::invalid_argument);
  EXPECT_THROW(makeChemistryEngine(GetParam(), m, {1, -1}, 1), InputError);
  auto engine = makeChemistryEngine(GetParam(), m, {0, 0}, 1);
  EXPECT_THROW(engine->setCopies(2, 0, 1), std::out_of_range);
  EXPECT_THROW(engine->setCopies(0, 1, 1), std::out_of_range);
  EXPECT_THROW(engine->setCopies(0, 0, -1), std::invalid_argument);
  const RateFactors factors = engine->claimRateFactors(m.ranges.front());
  EXPECT_THROW(factors.set(2, 0, 1.0), std::out_of_range);
  EXPECT_THROW(factors.set(0, 2, 1.0), std::out_of_range);
  EXPECT_THROW(factors.set(0, 0, -1.0), std::invalid_argument);
  EXPECT_THROW(factors.set(0, 0, std::nan("")), std::invalid_argument);
  // One owner per range.
  EXPECT_THROW(engine->claimRateFactors(m.ranges.front()), std::logic_error);
  EXPECT_THROW(engine->copies(0, 3), std::out_of_range);
  ChemistryModel bad = m;
  bad.species[0].diffusion = -1.0;
  EXPECT_THROW(makeChemistryEngine(GetParam(), bad, {0, 0}, 1), InputError);
}

INSTANTIATE_TEST_SUITE_P(Engines, Controls, ::testing::Values(EngineKind::kNextSubvolume, EngineKind::kDirect),
                         [](const auto& info) { return std::string(chemtest::engineName(info.param)); });

}  // namespace
}  // namespace cortex
