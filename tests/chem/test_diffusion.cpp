// Diffusion as hops between face neighbours (rate D/h^2 per copy and face), both engines.
// Stochastic tests with fixed seeds; tolerances 5 standard errors or chi-square p > 1e-4.
#include <gtest/gtest.h>

#include <cmath>

#include "chem_models.hpp"
#include "chem_statistics.hpp"

namespace cortex {
namespace {

constexpr double kH = 100.0;  // nm, compartment edge
constexpr double kD = 1.0e4;  // nm^2/s: one hop per copy, face and second

CompartmentGrid cube(int n) { return {kH, {n, n, n}}; }

ChemistryModel diffusionGrid(int n) {
  ChemistryModel m;
  m.volumes = gridGraph(cube(n));
  m.species.push_back({"A", kD});
  return m;
}

struct Release {
  EngineKind kind;
  int n;       // grid edge in compartments (odd, release in the middle)
  int copies;  // released
  std::vector<double> times;
};

class PointRelease : public ::testing::TestWithParam<Release> {};

// Copies released in the middle compartment are independent continuous-time random
// walks on the lattice: per axis the displacement has variance 2(D/h^2)t·h^2 = 2Dt
// exactly, so MSD = 6Dt and the mean stays at the release point, as long as no copy
// has met a wall (the walls are >= 5 standard deviations of the displacement away at
// the last time checked). Tolerance: 5 standard errors of the mean over copies.
TEST_P(PointRelease, SpreadsWithMeanSquaredDisplacementSixDt) {
  const Release& r = GetParam();
  const ChemistryModel m = diffusionGrid(r.n);
  const CompartmentGrid grid = cube(r.n);
  const int mid = r.n / 2;
  std::vector<int> copies(grid.count(), 0);
  copies[grid.index(mid, mid, mid)] = r.copies;
  auto engine = makeChemistryEngine(r.kind, m, copies, 21);

  for (double t : r.times) {
    engine->advance(t);
    std::vector<double> r2;
    std::array<std::vector<double>, 3> x;
    for (Index c = 0; c < grid.count(); ++c) {
      const auto ijk = grid.coords(c);
      double d2 = 0.0;
      std::array<double, 3> d{};
      for (int a = 0; a < 3; ++a) {
        d[a] = (ijk[a] - mid) * kH;
        d2 += d[a] * d[a];
      }
      for (int k = 0; k < engine->copies(c, 0); ++k) {
        r2.push_back(d2);
        for (int a = 0; a < 3; ++a) x[a].push_back(d[a]);
      }
    }
    ASSERT_EQ(static_cast<int>(r2.size()), r.copies);
    const chemtest::Moments msd = chemtest::moments(r2);
    EXPECT_NEAR(msd.mean, 6.0 * kD * t, 5.0 * msd.standardError) << "t = " << t;
    for (int a = 0; a < 3; ++a) {
      const chemtest::Moments mean = chemtest::moments(x[a]);
      EXPECT_NEAR(mean.mean, 0.0, 5.0 * mean.standardError) << "axis " << a << ", t = " << t;
    }
  }
}

// The direct method costs O(channels) per event, hence a smaller grid and fewer copies.
INSTANTIATE_TEST_SUITE_P(Engines, PointRelease,
                         ::testing::Values(Release{EngineKind::kNextSubvolume, 41, 10000, {1.0, 2.0, 4.0}},
                                           Release{EngineKind::kDirect, 21, 1000, {0.5, 1.0, 2.0}}),
                         [](const auto& info) { return std::string(chemtest::engineName(info.param.kind)); });

class UniformLimit : public ::testing::TestWithParam<EngineKind> {};

// Hop rates are symmetric, so at long times the copies are multinomial over the
// compartments with equal probabilities, whatever the start (here all in a corner).
// The slowest mode of the 5^3 grid decays at 2(1 - cos(pi/5))·D/h^2 ≈ 0.38/s: 60 s of
// burn-in leave e^-23 of the start, snapshots 12 s apart are independent (e^-4.6).
// Tolerance: the summed Pearson statistic over all snapshots, p > 1e-4.
TEST_P(UniformLimit, CopiesSpreadUniformlyOverCompartments) {
  const ChemistryModel m = diffusionGrid(5);
  const int copies = 1250, snapshots = 8;
  std::vector<int> initial(m.volumes.count(), 0);
  initial[0] = copies;
  auto engine = makeChemistryEngine(GetParam(), m, initial, 22);
  engine->advance(60.0);
  const double expected = static_cast<double>(copies) / m.volumes.count();
  double chi2 = 0.0;
  for (int s = 0; s < snapshots; ++s) {
    engine->advance(engine->time() + 12.0);
    ASSERT_EQ(chemtest::total(*engine, m.volumes.count(), 0), copies);
    for (Index c = 0; c < m.volumes.count(); ++c) chi2 += std::pow(engine->copies(c, 0) - expected, 2) / expected;
  }
  const int dof = snapshots * (m.volumes.count() - 1);
  EXPECT_GT(chemtest::chiSquarePValue(chi2, dof), 1e-4) << "chi2 " << chi2 << " dof " << dof;
  EXPECT_EQ(engine->diffusionEvents(), engine->events());
}

INSTANTIATE_TEST_SUITE_P(Engines, UniformLimit, ::testing::Values(EngineKind::kNextSubvolume, EngineKind::kDirect),
                         [](const auto& info) { return std::string(chemtest::engineName(info.param)); });

}  // namespace
}  // namespace cortex
