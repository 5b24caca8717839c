// Slicing the compartment grid by a closed membrane (thesis 2.2.4.2): the thesis'
// accuracy check of the planar-cut approximation, the total inside volume, and that a
// face shared by two compartments has one area fraction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "chem/compartment_slicing.hpp"
#include "core/random.hpp"
#include "mesh/icosphere.hpp"

namespace cortex {
namespace {

constexpr double kRadius = 800.0;  // nm
const Vec3 kCentre(1500.0, 1500.0, 1500.0);

CompartmentGrid thesisGrid() {
  CompartmentGrid g;
  g.size = 500.0;
  g.shape = {6, 6, 6};
  return g;
}

// The thesis' check: a 0.8 µm sphere centred in a 6x6x6 grid of 500 nm compartments;
// for every cut compartment the planar-cut volume against a Monte Carlo estimate of the
// exact sphere. The thesis reports an average relative error below 4% with 10,000
// samples per compartment; with that few, the Monte Carlo noise on thin slivers alone
// moves the average between 3.1% and 4.6% from seed to seed, so this test uses 200,000
// (measured 2.2% here; 1.9% with 10^6, i.e. the planar cut's own error). The mesh is
// the icosphere with 5 subdivisions (edges ~ 30 nm).
TEST(CompartmentSlicing, ThesisSphereCheckAverageRelativeErrorBelowFourPercent) {
  const CompartmentGrid grid = thesisGrid();
  const TriangleSoup sphere = icosphere(kCentre, kRadius, 5);
  const CompartmentSlices s = sliceCompartments(sphere.positions, sphere.triangles, grid);
  RandomStream random(7, StreamId::kInitialConditions);
  constexpr int kSamples = 200000;
  double sum_error = 0.0;
  int cut = 0;
  for (Index c = 0; c < grid.count(); ++c) {
    if (!s.cut[c]) continue;
    const auto ijk = grid.coords(c);
    int hits = 0;
    for (int n = 0; n < kSamples; ++n) {
      const Vec3 x((ijk[0] + random.uniform()) * grid.size, (ijk[1] + random.uniform()) * grid.size,
                   (ijk[2] + random.uniform()) * grid.size);
      if ((x - kCentre).norm() < kRadius) ++hits;
    }
    const double monte_carlo = static_cast<double>(hits) / kSamples;
    ASSERT_GT(monte_carlo, 0.0) << "compartment " << c;
    sum_error += std::abs(s.volume[c] - monte_carlo) / monte_carlo;
    ++cut;
  }
  const double average = sum_error / cut;
  RecordProperty("average_relative_error", std::to_string(average));
  std::printf("thesis slicing check: %d cut compartments, average relative error %.4f\n", cut, average);
  EXPECT_GT(cut, 0);
  EXPECT_LT(average, 0.04);
}

TEST(CompartmentSlicing, TotalInsideVolumeWithinOnePercentOfSphere) {
  const CompartmentGrid grid = thesisGrid();
  const TriangleSoup sphere = icosphere(kCentre, kRadius, 5);
  const CompartmentSlices s = sliceCompartments(sphere.positions, sphere.triangles, grid);
  double total = 0.0;
  for (double f : s.volume) total += f * grid.volume();
  const double exact = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;
  EXPECT_NEAR(total / exact, 1.0, 0.01);
}

TEST(CompartmentSlicing, SharedFacesHaveOneFractionAndValuesAreInRange) {
  const CompartmentGrid grid = thesisGrid();
  // Off-centre so that the sphere cuts faces at all sorts of positions.
  const TriangleSoup sphere = icosphere(Vec3(1430.0, 1570.0, 1515.0), 900.0, 4);
  const CompartmentSlices s = sliceCompartments(sphere.positions, sphere.triangles, grid);
  for (Index c = 0; c < grid.count(); ++c) {
    EXPECT_GE(s.volume[c], 0.0);
    EXPECT_LE(s.volume[c], 1.0);
    const auto ijk = grid.coords(c);
    for (int k = 0; k < 3; ++k) {
      for (int f = 0; f < 2; ++f) {
        EXPECT_GE(s.faces[c][2 * k + f], 0.0);
        EXPECT_LE(s.faces[c][2 * k + f], 1.0);
      }
      if (ijk[k] + 1 >= grid.shape[k]) continue;
      auto n = ijk;
      ++n[k];
      EXPECT_EQ(s.faces[c][2 * k + 1], s.faces[grid.index(n[0], n[1], n[2])][2 * k]);
    }
  }
  // Centre compartments are wholly inside, corners wholly outside.
  EXPECT_EQ(s.volume[grid.index(2, 3, 3)], 1.0);
  EXPECT_EQ(s.volume[grid.index(0, 0, 0)], 0.0);
}

// A plane cut is exact: a flat box-shaped membrane whose top face lies at z = 650 nm
// leaves 30% of the second layer's compartments inside.
TEST(CompartmentSlicing, PlanarMembraneIsSlicedExactly) {
  CompartmentGrid grid;
  grid.size = 500.0;
  grid.shape = {2, 2, 3};
  // Closed box [-100, 1100]^2 x [-100, 650], outward oriented.
  const double lo = -100.0, hi = 1100.0, top = 650.0;
  std::vector<Vec3> x{{lo, lo, lo}, {hi, lo, lo}, {hi, hi, lo}, {lo, hi, lo},
                      {lo, lo, top}, {hi, lo, top}, {hi, hi, top}, {lo, hi, top}};
  std::vector<Tri> t{{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                     {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  const CompartmentSlices s = sliceCompartments(x, t, grid);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      EXPECT_EQ(s.volume[grid.index(i, j, 0)], 1.0);
      EXPECT_NEAR(s.volume[grid.index(i, j, 1)], 0.3, 1e-12);
      EXPECT_EQ(s.volume[grid.index(i, j, 2)], 0.0);
      const auto& f = s.faces[grid.index(i, j, 1)];
      EXPECT_NEAR(f[0], 0.3, 1e-12);
      EXPECT_NEAR(f[4], 1.0, 1e-12);
      EXPECT_NEAR(f[5], 0.0, 1e-12);
    }
}

// How small a vesicle the planar cut can slice (the reason for the warning below two
// compartments across, confinement.hpp): spheres of diameter 1-3 compartments at 20
// random places in the grid, the total volume inside against 4/3 pi R^3. Measured: worst
// error 0.4% at 3 across, 1.1% at 2, 5.8% at 1.5 and 19% at 1 (mean 10%).
TEST(CompartmentSlicing, TheVolumeErrorGrowsAsTheVesicleShrinksToACompartment) {
  CompartmentGrid grid;
  grid.size = 500.0;
  grid.shape = {8, 8, 8};
  RandomStream random(3, StreamId::kInitialConditions);
  const auto errors = [&](double across) {
    double worst = 0.0, sum = 0.0;
    constexpr int kPlaces = 20;
    for (int k = 0; k < kPlaces; ++k) {
      const double r = 0.5 * across * grid.size;
      const Vec3 c = Vec3(2000.0, 2000.0, 2000.0) + grid.size * Vec3(random.uniform(), random.uniform(), random.uniform());
      const TriangleSoup sphere = icosphere(c, r, 5);
      const CompartmentSlices s = sliceCompartments(sphere.positions, sphere.triangles, grid);
      double total = 0.0;
      for (double f : s.volume) total += f * grid.volume();
      const double error = std::abs(total / (4.0 / 3.0 * std::numbers::pi * r * r * r) - 1.0);
      worst = std::max(worst, error);
      sum += error;
    }
    return std::pair{sum / kPlaces, worst};
  };
  EXPECT_LT(errors(3.0).second, 0.01);
  EXPECT_LT(errors(2.0).second, 0.02);
  const auto [mean_at_one, worst_at_one] = errors(1.0);
  EXPECT_GT(mean_at_one, 0.05);  // what the warning is for
  EXPECT_GT(worst_at_one, 0.1);
}

}  // namespace
}  // namespace cortex
