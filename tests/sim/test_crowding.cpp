// The crowding cap of membrane species (issue 14; thesis 3.2.1, n ≤ n₀): with a footprint
// a, vertex j holds at most c_j = floor(|C_j|/a) copies; hops into a full vertex and
// reactions that would overfill it are void. Copies hopping at k_ij with |C_i| k_ij =
// |C_j| k_ji are then stationary in the product of truncated Poisson weights,
//   π(n) ∝ Π_j |C_j|^{n_j} / n_j!  for n_j ≤ c_j, Σ n_j = N,
// (detailed balance: the rate i → j is k_ij n_i while j is not full). Each vertex's
// occupancy follows from it exactly (a convolution over the other vertices). On an
// irregular 49-vertex patch with caps of 0 to 3 and N at 70% of the room, 1500 samples
// 5 mixing times apart: the occupancy of four vertices against the exact marginals by
// chi-square (p > 1e-3 each, both engines), and no vertex ever over its cap. Without the
// cap the same test fails (the copies pile on the big cells).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "chem/chem_statistics.hpp"
#include "chem/chemistry_engine.hpp"
#include "chem/two_copies.hpp"
#include "sim/surface_graph.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

constexpr double kFootprint = 900.0;  // nm^2

// Π_j (Σ_{k ≤ c_j} w_j^k/k! z^k) without factor `skip`: coefficients of z^0..z^N.
std::vector<double> partition(const std::vector<double>& w, const std::vector<int>& cap, int total, Index skip) {
  std::vector<double> z(static_cast<std::size_t>(total) + 1, 0.0);
  z[0] = 1.0;
  for (std::size_t j = 0; j < w.size(); ++j) {
    if (static_cast<Index>(j) == skip) continue;
    std::vector<double> next(z.size(), 0.0);
    double term = 1.0;
    for (int k = 0; k <= cap[j]; ++k) {
      for (std::size_t m = 0; m + k < z.size(); ++m) next[m + k] += z[m] * term;
      term *= w[j] / (k + 1);
    }
    z.swap(next);
  }
  return z;
}

class Crowding : public ::testing::TestWithParam<EngineKind> {};

TEST_P(Crowding, OccupancyFollowsTheTruncatedPoissonProduct) {
  SurfaceMesh mesh = testing::patchMesh(300.0, 50.0);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> jitter(-12.0, 12.0);
  for (Index v = 0; v < mesh.numVertices(); ++v)
    if (!mesh.isBoundaryVertex(v)) mesh.positions()[v] += Vec3(jitter(rng), jitter(rng), 0.0);
  const SubvolumeGraph g = dualCellGraph(mesh).graph;
  const Index n = g.count();
  std::vector<int> cap(static_cast<std::size_t>(n));
  std::vector<double> w(static_cast<std::size_t>(n));
  const double mean_cell = [&] {
    double a = 0.0;
    for (double s : g.size) a += s;
    return a / static_cast<double>(n);
  }();
  int room = 0;
  for (Index v = 0; v < n; ++v) {
    cap[v] = static_cast<int>(std::floor(g.size[v] / kFootprint));
    w[v] = g.size[v] / mean_cell;  // scaled: only ratios matter
    room += cap[v];
  }
  const int total = static_cast<int>(0.7 * room);
  std::vector<int> copies(static_cast<std::size_t>(n), 0);
  for (int placed = 0; placed < total;) {
    const Index v = std::uniform_int_distribution<Index>(0, n - 1)(rng);
    if (copies[v] < cap[v]) ++copies[v], ++placed;
  }

  ChemistryModel model;
  model.surfaces = {"patch"};
  model.species = {SpeciesDef{"P", 3.0e5, 0, kFootprint}};
  auto engine = makeChemistryEngine(GetParam(), model, {0}, 17);
  engine->setSurface(0, g, std::vector<Index>(static_cast<std::size_t>(n), 0), copies);

  // Four vertices: the two with the largest cap, one of cap 1, one in between.
  std::vector<Index> watched;
  for (int c : {3, 2, 1}) {
    for (Index v = 0; v < n && watched.size() < 4; ++v)
      if (cap[v] == c && (watched.size() < 2 || cap[watched.back()] != c)) watched.push_back(v);
  }
  ASSERT_GE(watched.size(), 3u);
  std::vector<std::vector<int>> samples(watched.size());
  const double spacing = 0.2;  // s; ~5 mixing times of the 7-edge-wide patch at D = 3e5 nm²/s
  int over_cap = 0;
  for (int k = 1; k <= 1500; ++k) {
    engine->advance(k * spacing);
    for (Index v = 0; v < n; ++v) over_cap += engine->copies(engine->regionStart(1) + v, 0) > cap[v];
    for (std::size_t a = 0; a < watched.size(); ++a) samples[a].push_back(engine->copies(engine->regionStart(1) + watched[a], 0));
  }
  EXPECT_EQ(over_cap, 0);
  const std::vector<double> z = partition(w, cap, total, -1);
  for (std::size_t a = 0; a < watched.size(); ++a) {
    const Index v = watched[a];
    const std::vector<double> others = partition(w, cap, total, v);
    const auto marginal = [&](int k) {
      if (k > cap[v] || k > total) return 0.0;
      return std::pow(w[v], k) / std::tgamma(k + 1.0) * others[total - k] / z[total];
    };
    const chemtest::ChiSquare fit = chemtest::goodnessOfFit(samples[a], marginal);
    EXPECT_GT(fit.p, 1e-3) << "vertex " << v << " (cap " << cap[v] << "): chi2 " << fit.statistic << " on "
                           << fit.dof << " dof";
  }
}

// Two species with footprints share a cell's area (Σ_s n_s a_s ≤ |C_j|): one copy of P and
// one of Q, a_P = a_Q = 0.55 of the mean cell, on an irregular 14-vertex patch. The joint
// positions (p, q) are stationary ∝ |C_p||C_q| on the states that fit (a cell holds both
// only if it has 1.1 mean cells of area). Power: caps per species (either copy fits alone)
// would admit p = q in the cells between 0.55 and 1.1 mean cells, of which the patch has
// some (asserted), and fail.
TEST_P(Crowding, TwoSpeciesShareTheArea) {
  const SurfaceMesh mesh = testing::irregularSmallPatch();
  const SubvolumeGraph g = dualCellGraph(mesh).graph;
  const Index n = g.count();
  double mean_cell = 0.0;
  for (double a : g.size) mean_cell += a / static_cast<double>(n);
  const double footprint = 0.55 * mean_cell;
  auto fits = [&](Index p, Index q) {
    if (g.size[p] < footprint || g.size[q] < footprint) return false;
    return p != q || g.size[p] >= 2.0 * footprint;
  };
  int shared_by_one_cap_only = 0;
  for (Index v = 0; v < n; ++v) shared_by_one_cap_only += g.size[v] >= footprint && !fits(v, v);
  ASSERT_GT(shared_by_one_cap_only, 0);

  ChemistryModel model;
  model.surfaces = {"patch"};
  model.species = {SpeciesDef{"G", 0.0}, SpeciesDef{"P", 1.0e6, 0, footprint}, SpeciesDef{"Q", 1.0e6, 0, footprint}};
  auto engine = makeChemistryEngine(GetParam(), model, {0, 0, 0}, 43);
  Index p0 = 0;
  while (g.size[p0] < 2.0 * footprint) ++p0;  // a cell that holds both to start with
  std::vector<int> start(3 * static_cast<std::size_t>(n), 0);
  start[3 * p0 + 1] = start[3 * p0 + 2] = 1;
  engine->setSurface(0, g, std::vector<Index>(static_cast<std::size_t>(n), 0), start);
  const std::vector<int> samples = chemtest::sampleTwoCopies(*engine, n, 8000, 0.04);
  for (int a : samples) {
    const Index p = a / n, q = a % n;
    ASSERT_TRUE(fits(p, q)) << "both copies in cell " << p << " of " << g.size[p] / mean_cell << " mean cells";
  }
  const chemtest::ChiSquare fit = chemtest::fitTwoCopies(
      samples, n, [&](Index p, Index q) { return fits(p, q) ? g.size[p] * g.size[q] : 0.0; });
  EXPECT_GT(fit.p, 1e-3) << "chi2 " << fit.statistic << " on " << fit.dof << " dof";
}

INSTANTIATE_TEST_SUITE_P(BothEngines, Crowding, ::testing::Values(EngineKind::kNextSubvolume, EngineKind::kDirect),
                         [](const auto& info) { return info.param == EngineKind::kDirect ? "direct" : "nsm"; });

}  // namespace
}  // namespace cortex
