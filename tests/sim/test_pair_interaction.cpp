// The mean-field pair attraction of membrane proteins (issue 14; thesis eqs. 3.4–3.5;
// sim/pair_interaction.hpp):
//   - the kernel gives R = μ₀ n + μ₂ Δn: on an equilateral patch the cotangent Laplacian
//     is the six-point stencil, exact for a quadratic density, so R matches the closed
//     form at every vertex with a regular one-ring (1e-5 of the μ₂ Δn term: the patch's rows are
//     equilateral to 2e-6);
//   - the engines keep the exact stationary distribution of interacting copies,
//       π(N) ∝ Π_j |C_j|^{N_j}/N_j! · exp(−Σ V_j N_j − ½ Nᵀ K N + ½ Σ K_jj N_j), N_j ≤ cap_j,
//     (pairs without self-pairs): 3 copies on an irregular 14-vertex patch with a strong
//     kernel (μ₀/|C| ≈ −1 k_BT), a ramp potential and the crowding cap; 8000 samples
//     10 mixing times apart, chi-square over all states (p > 1e-3), both engines.
//     Power: biasing hops by R_k − R_i alone (forgetting that the moving copy leaves its
//     own field, − K_ik + K_ii) fails at p < 1e-30.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <random>

#include "chem/chem_statistics.hpp"
#include "chem/chemistry_engine.hpp"
#include "sim/pair_interaction.hpp"
#include "mesh/planar_patch.hpp"
#include "sim/surface_graph.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

TEST(PairInteraction, KernelIsMeanFieldOfAQuadraticDensity) {
  // 20 rows of 20 nm triangles: height 17.32 nm (planarPatch rounds the row count up).
  const SurfaceMesh mesh = SurfaceMesh::fromSoup(planarPatch(Vec3::Zero(), 400.0, 346.41, 20.0), "equilateral");
  const SubvolumeGraph g = dualCellGraph(mesh).graph;
  const PairMoments m = gaussianPairMoments(0.2, 18.0);
  EXPECT_NEAR(m.mu0, -M_PI * 0.2 * 324.0, 1e-9);
  EXPECT_NEAR(m.mu2, -M_PI * 0.2 * 324.0 * 324.0 / 4.0, 1e-6);
  const auto k = pairInteraction(g, m, std::vector<double>(static_cast<std::size_t>(g.count()), 0.0),
                                 DriftScheme::kExponential);
  // n = 0.01 + 1e-6 (x − 150)² + 2e-6 y² copies/nm², so Δn = 6e-6.
  auto density = [](const Vec3& x) { return 0.01 + 1e-6 * (x[0] - 150.0) * (x[0] - 150.0) + 2e-6 * x[1] * x[1]; };
  std::vector<double> copies(static_cast<std::size_t>(g.count()));
  for (Index v = 0; v < g.count(); ++v) copies[v] = density(mesh.positions()[v]) * g.size[v];
  int interior = 0;
  for (Index v = 0; v < g.count(); ++v) {
    // Away from the boundary, whose rows end in half triangles.
    bool regular = !mesh.isBoundaryVertex(v);
    for (Index e = g.start[v]; e < g.start[v + 1]; ++e) regular = regular && !mesh.isBoundaryVertex(g.target[e]);
    if (!regular) continue;
    double r = k.self[v] * copies[v];
    for (Index e = g.start[v]; e < g.start[v + 1]; ++e) r += k.pair[e] * copies[g.target[e]];
    const double expected = m.mu0 * density(mesh.positions()[v]) + m.mu2 * 6e-6;
    EXPECT_NEAR(r, expected, 1e-5 * std::abs(m.mu2 * 6e-6)) << "vertex " << v;
    ++interior;
  }
  EXPECT_GT(interior, 250);
}

class PairStationary : public ::testing::TestWithParam<EngineKind> {};

TEST_P(PairStationary, JointStateFollowsThePairEnergy) {
  SurfaceMesh mesh = testing::patchMesh(200.0, 100.0);
  for (Index v = 0; v < mesh.numVertices(); ++v)
    if (!mesh.isBoundaryVertex(v)) mesh.positions()[v] += Vec3(23.0, -14.0, 0.0);
  const SubvolumeGraph g = dualCellGraph(mesh).graph;
  const Index n = g.count();
  ASSERT_EQ(n, 14);
  double mean_cell = 0.0;
  for (double a : g.size) mean_cell += a / static_cast<double>(n);
  // μ₀/|C| ≈ −1 k_BT; σ = 60 nm.
  const double range = 60.0, height = mean_cell / (M_PI * range * range);
  std::vector<double> potential(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v) potential[v] = 0.008 * mesh.positions()[v][0];
  const auto k = pairInteraction(g, gaussianPairMoments(height, range), potential, DriftScheme::kExponential);
  const double footprint = mean_cell / 2.2;
  std::vector<int> cap(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v) cap[v] = static_cast<int>(std::floor(g.size[v] / footprint));

  // Every state of 3 copies within the caps, and its weight.
  constexpr int kCopies = 3;
  std::vector<std::vector<int>> states;
  std::function<void(std::vector<int>&, Index, int)> enumerate = [&](std::vector<int>& N, Index v, int left) {
    if (v == n) {
      if (left == 0) states.push_back(N);
      return;
    }
    for (int c = 0; c <= std::min(left, cap[v]); ++c) {
      N[v] = c;
      enumerate(N, v + 1, left - c);
    }
    N[v] = 0;
  };
  std::vector<int> start(static_cast<std::size_t>(n), 0);
  enumerate(start, 0, kCopies);
  ASSERT_GT(states.size(), 150u);
  std::vector<double> weight;
  double z = 0.0;
  for (const auto& N : states) {
    double log_w = 0.0;
    for (Index j = 0; j < n; ++j) {
      log_w += N[j] * (std::log(g.size[j] / mean_cell) - potential[j]) - std::lgamma(N[j] + 1.0);
      double r = k.self[j] * N[j];
      for (Index e = g.start[j]; e < g.start[j + 1]; ++e) r += k.pair[e] * N[g.target[e]];
      log_w -= 0.5 * N[j] * r - 0.5 * k.self[j] * N[j];
    }
    weight.push_back(std::exp(log_w));
    z += weight.back();
  }
  std::map<std::vector<int>, int> index;
  for (std::size_t a = 0; a < states.size(); ++a) index[states[a]] = static_cast<int>(a);

  ChemistryModel model;
  model.surfaces = {"patch"};
  model.species = {SpeciesDef{"P", 1.0e6, 0, footprint}};
  auto engine = makeChemistryEngine(GetParam(), model, {0}, 23);
  engine->setSurface(0, g, std::vector<Index>(static_cast<std::size_t>(n), 0), states.front());
  engine->setSurfaceInteraction(0, k);
  std::vector<int> samples;
  std::vector<int> N(static_cast<std::size_t>(n));
  for (int s = 1; s <= 8000; ++s) {
    engine->advance(0.04 * s);  // ~10 relaxation times of the 200 nm patch at D = 1e6 nm²/s
    for (Index v = 0; v < n; ++v) N[v] = engine->copies(engine->regionStart(1) + v, 0);
    ASSERT_TRUE(index.count(N)) << "a state over the cap or with copies lost";
    samples.push_back(index[N]);
  }
  const chemtest::ChiSquare fit =
      chemtest::goodnessOfFit(samples, [&](int a) { return a < static_cast<int>(weight.size()) ? weight[a] / z : 0.0; });
  EXPECT_GT(fit.p, 1e-3) << "chi2 " << fit.statistic << " on " << fit.dof << " dof";
}

INSTANTIATE_TEST_SUITE_P(BothEngines, PairStationary,
                         ::testing::Values(EngineKind::kNextSubvolume, EngineKind::kDirect),
                         [](const auto& info) { return info.param == EngineKind::kDirect ? "direct" : "nsm"; });

}  // namespace
}  // namespace cortex
