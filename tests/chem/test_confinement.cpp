// Membrane confinement in both engines (ChemistryEngine::setConfinement, docs/chemistry.md): with hop rates D·a_ij/(h²·f_i) the stationary distribution of a confined
// diffusing species is uniform in the confined volume (copies per compartment ∝ f);
// inactive compartments never hold a copy; copies stranded by a moving membrane are
// moved, never lost; reaction propensities scale with the volume. Fixed seeds;
// tolerances: chi-square p > 1e-4, means within 5 standard errors.
#include <gtest/gtest.h>

#include <cmath>

#include "chem/compartment_slicing.hpp"
#include "chem_models.hpp"
#include "chem_statistics.hpp"
#include "mesh/icosphere.hpp"

namespace cortex {
namespace {

constexpr double kH = 100.0;  // nm
constexpr double kD = 1.0e4;  // nm^2/s: one hop per copy, full face and second

const CompartmentGrid kGrid{kH, {4, 4, 4}};

ChemistryModel sphereGrid() {
  ChemistryModel m;
  m.volumes = gridGraph(kGrid);
  m.species.push_back({"A", kD});
  return m;
}

CompartmentSlices sliceSphere(const Vec3& centre, double radius) {
  const TriangleSoup s = icosphere(centre, radius, 3);
  return sliceCompartments(s.positions, s.triangles, kGrid);
}

void confine(ChemistryEngine& engine, const CompartmentSlices& s) {
  engine.setConfinement(0, s.volume, gridEdgeValues(kGrid, s.faces));
}

void expectNoneInactive(const ChemistryEngine& e, const CompartmentSlices& s, Index species) {
  for (Index c = 0; c < static_cast<Index>(s.volume.size()); ++c)
    if (s.volume[c] == 0.0) { ASSERT_EQ(e.copies(c, species), 0) << "compartment " << c; }
}

class Confinement : public ::testing::TestWithParam<EngineKind> {};

// 150 copies inside a sphere of radius 170 nm cutting a 4x4x4 grid of 100 nm
// compartments. Slowest diffusion mode ~ (400 nm / π)² / D ≈ 1.6 s; samples 8 s apart.
// Pooled over independent samples the counts are multinomial with p_c ∝ f_c.
TEST_P(Confinement, StationaryDistributionIsUniformInVolume) {
  const ChemistryModel m = sphereGrid();
  const CompartmentSlices s = sliceSphere(Vec3(200.0, 200.0, 200.0), 170.0);
  const Index C = kGrid.count();
  std::vector<int> copies(C, 0);
  copies[kGrid.index(1, 1, 1)] = 150;
  auto engine = makeChemistryEngine(GetParam(), m, copies, 21);
  confine(*engine, s);
  const int samples = GetParam() == EngineKind::kDirect ? 150 : 400;
  std::vector<double> counts(C, 0.0);
  engine->advance(20.0);
  for (int k = 0; k < samples; ++k) {
    engine->advance(engine->time() + 8.0);
    expectNoneInactive(*engine, s, 0);
    for (Index c = 0; c < C; ++c) counts[c] += engine->copies(c, 0);
  }
  double total_f = 0.0;
  for (double f : s.volume) total_f += f;
  // Chi-square over compartments expecting >= 5, the rest merged into one bin.
  const double n = 150.0 * samples;
  double chi2 = 0.0, rest_expected = 0.0, rest_observed = 0.0;
  int bins = 0;
  for (Index c = 0; c < C; ++c) {
    if (s.volume[c] == 0.0) continue;
    const double expected = n * s.volume[c] / total_f;
    if (expected < 5.0) {
      rest_expected += expected;
      rest_observed += counts[c];
      continue;
    }
    chi2 += (counts[c] - expected) * (counts[c] - expected) / expected;
    ++bins;
  }
  if (rest_expected > 0.0) {
    chi2 += (rest_observed - rest_expected) * (rest_observed - rest_expected) / rest_expected;
    ++bins;
  }
  const double p = chemtest::chiSquarePValue(chi2, bins - 1);
  EXPECT_GT(p, 1e-4) << "chi2 " << chi2 << " dof " << bins - 1;
}

// The membrane shrinks and moves twice over a long run: copies left in compartments
// that became inactive move to the nearest active one; the total never changes and no
// copy is ever in an inactive compartment.
TEST_P(Confinement, MovingMembraneNeverLosesOrStrandsCopies) {
  const ChemistryModel m = sphereGrid();
  const Index C = kGrid.count();
  std::vector<int> copies(C, 0);
  copies[kGrid.index(1, 2, 1)] = 300;
  auto engine = makeChemistryEngine(GetParam(), m, copies, 22);
  const std::vector<std::pair<Vec3, double>> shapes{
      {Vec3(200.0, 200.0, 200.0), 190.0}, {Vec3(180.0, 210.0, 200.0), 120.0}, {Vec3(260.0, 250.0, 230.0), 90.0}};
  for (const auto& [centre, radius] : shapes) {
    const CompartmentSlices s = sliceSphere(centre, radius);
    confine(*engine, s);
    expectNoneInactive(*engine, s, 0);
    EXPECT_EQ(chemtest::total(*engine, C, 0), 300);
    for (int k = 0; k < 20; ++k) {
      engine->advance(engine->time() + 1.0);
      expectNoneInactive(*engine, s, 0);
    }
    EXPECT_EQ(chemtest::total(*engine, C, 0), 300);
  }
  EXPECT_GT(engine->diffusionEvents(), 0);
}

// -> A, A -> in half a compartment: the inflow k·N·V scales by f = 0.5, so the mean
// copy number halves; the bimolecular 2 A -> is unchanged in concentration terms.
TEST_P(Confinement, ZeroOrderPropensityScalesWithVolume) {
  ChemistryModel m = chemtest::wellMixed({"A"}, {{"-> A", 0.0}, {"A ->", 1.0}});
  m.reactions[0].rate = 40.0 / copiesPerMicromolar(m.volumes.size[0]);
  auto engine = makeChemistryEngine(GetParam(), m, {0}, 23);
  engine->setConfinement(0, {0.5}, {});  // one compartment: no edges
  engine->advance(10.0);
  const std::vector<int> n = chemtest::sample(*engine, 5.0, 4000, [](const auto& e) { return e.copies(0, 0); });
  const chemtest::Moments mo = chemtest::moments(n);
  EXPECT_NEAR(mo.mean, 20.0, 5.0 * mo.standardError);
  // Copies with nowhere to go are refused, not lost.
  EXPECT_THROW(engine->setConfinement(0, {0.0}, {}), std::runtime_error);
  // Empty and inactive: nothing is born, and setting copies there is refused.
  engine->setConfinement(0, {1.0}, {});
  engine->setCopies(0, 0, 0);
  engine->setConfinement(0, {0.0}, {});
  engine->advance(engine->time() + 10.0);
  EXPECT_EQ(engine->copies(0, 0), 0);
  EXPECT_THROW(engine->setCopies(0, 0, 1), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(BothEngines, Confinement,
                         ::testing::Values(EngineKind::kNextSubvolume, EngineKind::kDirect),
                         [](const auto& info) { return chemtest::engineName(info.param); });

}  // namespace
}  // namespace cortex
