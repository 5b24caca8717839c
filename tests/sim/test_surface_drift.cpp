// Membrane species in a potential (issue 14): with the drift factors of
// sim/surface_drift.hpp the hops keep copies stationary in proportion to |C_j| e^{−βV_j}
// on an irregular mesh.
//
// The copies are independent, so a chain started in the stationary distribution stays
// in it: 10⁵ copies are drawn from |C_j| e^{−βV_j}, hop for 0.5 s (~120 hops each, far
// more than a local error needs to show) and their final counts per vertex are one
// multinomial sample of that distribution: Pearson's chi-square over the vertices
// (those expecting >= 5 copies, the rest pooled), p > 1e-3. Run with
//   - a smooth Gaussian stripe (2 k_BT, 150 nm wide, per-edge |βΔV| <= 0.5): both the
//     exponential and the linear drift pass;
//   - a steep well (−7 k_BT, 45 nm wide, per-edge |βΔV| up to >5, most copies on its
//     steep flanks): the exponential (Scharfetter–Gummel) drift passes, and the linear
//     one fails (p < 1e-6), which is what docs/proteins.md says of it beyond |βΔV| ≈ 2
//     per edge. Power: scaling the exponential scheme's x by 0.95 (a 5% error in the
//     potential) fails this test at p ~ 1e-25.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "chem/chem_statistics.hpp"
#include "chem/chemistry_engine.hpp"
#include "sim/surface_drift.hpp"
#include "sim/surface_graph.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

// A 1 µm patch of 50 nm edges, interior vertices moved at random in the plane by up to
// 0.35 edge lengths (an irregular mesh; a few edges may lose the Delaunay property and
// are then closed both ways, which keeps detailed balance).
SurfaceMesh irregularPatch(unsigned seed) {
  SurfaceMesh mesh = testing::patchMesh(1000.0, 50.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-17.5, 17.5);
  for (Index v = 0; v < mesh.numVertices(); ++v)
    if (!mesh.isBoundaryVertex(v)) mesh.positions()[v] += Vec3(u(rng), u(rng), 0.0);
  return mesh;
}

struct StationaryCheck {
  double p = 0.0;          // chi-square p-value
  double largest_step = 0.0;  // largest |βΔV| over the mesh's edges
};

StationaryCheck stationaryCheck(const SurfacePotentialConfig& potential, DriftScheme scheme) {
  const SurfaceMesh mesh = irregularPatch(7);
  const DualCellGraph cells = dualCellGraph(mesh);
  const SubvolumeGraph& g = cells.graph;
  const Index n = g.count();
  std::vector<double> h(static_cast<std::size_t>(n)), weight(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v) {
    h[v] = surfacePotential(potential, mesh.positions()[v]);
    weight[v] = g.size[v] * std::exp(-h[v]);
  }
  StationaryCheck out;
  for (Index v = 0; v < n; ++v)
    for (Index e = g.start[v]; e < g.start[v + 1]; ++e) out.largest_step = std::max(out.largest_step, std::abs(h[g.target[e]] - h[v]));

  constexpr int kCopies = 100000;
  std::mt19937 rng(3);
  std::discrete_distribution<Index> draw(weight.begin(), weight.end());
  std::vector<int> copies(static_cast<std::size_t>(n), 0);
  for (int k = 0; k < kCopies; ++k) ++copies[draw(rng)];

  ChemistryModel model;  // one 500 nm compartment holds the whole patch
  model.surfaces = {"patch"};
  model.species = {SpeciesDef{"P", 1.0e5, 0}};
  auto engine = makeChemistryEngine(EngineKind::kNextSubvolume, model, {0}, 11);
  engine->setSurface(0, g, std::vector<Index>(static_cast<std::size_t>(n), 0), copies);
  engine->setSurfaceDrift(0, driftFactors(g, h, scheme).factors);
  engine->advance(0.5);
  EXPECT_GT(engine->diffusionEvents(), 50LL * kCopies);

  double total_weight = 0.0;
  for (double w : weight) total_weight += w;
  double chi2 = 0.0, pooled_expected = 0.0, pooled_observed = 0.0;
  int bins = 0;
  for (Index v = 0; v < n; ++v) {
    const double expected = kCopies * weight[v] / total_weight;
    const int observed = engine->copies(engine->regionStart(1) + v, 0);
    if (expected < 5.0) {
      pooled_expected += expected, pooled_observed += observed;
      continue;
    }
    chi2 += (observed - expected) * (observed - expected) / expected;
    ++bins;
  }
  if (pooled_expected > 0.0) {
    chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++bins;
  }
  out.p = chemtest::chiSquarePValue(chi2, bins - 1);
  return out;
}

SurfacePotentialConfig stripe(double height, double width) {
  SurfacePotentialConfig p;
  p.kind = SurfacePotentialConfig::Kind::kGaussianStripe;
  p.axis = 0;
  p.center = 0.0;  // the patch spans [-500, 500] nm
  p.height = height;
  p.width = width;
  return p;
}

TEST(SurfaceDrift, BernoulliFactorsAreInDetailedBalanceAndLinearOnesCloseBothWays) {
  SubvolumeGraph g;  // two cells of equal size, one edge each way
  g.size = {1.0, 1.0};
  g.start = {0, 1, 2};
  g.target = {1, 0};
  g.hop_length2 = {1.0, 1.0};
  for (double x : {1e-14, 0.3, 2.0, 5.0, 30.0}) {
    const DriftFactors e = driftFactors(g, {0.0, x}, DriftScheme::kExponential);
    EXPECT_NEAR(e.factors[0] / e.factors[1], std::exp(-x), 1e-12 * std::exp(-x)) << x;
    const DriftFactors l = driftFactors(g, {0.0, x}, DriftScheme::kLinear);
    if (x < 2.0) {
      EXPECT_DOUBLE_EQ(l.factors[0], 1.0 - x / 2) << x;
      EXPECT_DOUBLE_EQ(l.factors[1], 1.0 + x / 2) << x;
      EXPECT_EQ(l.closed_edges, 0);
    } else {
      EXPECT_EQ(l.factors[0], 0.0) << x;
      EXPECT_EQ(l.factors[1], 0.0) << x;
      EXPECT_EQ(l.closed_edges, 1);
    }
  }
  EXPECT_NEAR(driftFactors(g, {0.0, 0.0}, DriftScheme::kExponential).factors[0], 1.0, 1e-15);
}

TEST(SurfaceDrift, SmoothPotentialIsStationaryAtBoltzmannWeightsWithBothSchemes) {
  for (DriftScheme scheme : {DriftScheme::kExponential, DriftScheme::kLinear}) {
    const StationaryCheck c = stationaryCheck(stripe(2.0, 150.0), scheme);
    EXPECT_LT(c.largest_step, 0.6);
    EXPECT_GT(c.p, 1e-3) << (scheme == DriftScheme::kLinear ? "linear" : "exponential");
  }
}

TEST(SurfaceDrift, SteepWellIsStationaryWithTheExponentialSchemeOnly) {
  const StationaryCheck exponential = stationaryCheck(stripe(-7.0, 45.0), DriftScheme::kExponential);
  EXPECT_GT(exponential.largest_step, 5.0);
  EXPECT_GT(exponential.p, 1e-3);
  const StationaryCheck linear = stationaryCheck(stripe(-7.0, 45.0), DriftScheme::kLinear);
  EXPECT_LT(linear.p, 1e-6) << "the linear drift should be visibly wrong at per-edge steps above 2";
}

}  // namespace
}  // namespace cortex
