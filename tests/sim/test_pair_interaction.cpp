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
//     own field, − K_ik + K_ii) fails at p < 1e-30;
//   - the same copies binding from a 3-copy bulk and unbinding at r e^{V_j + R_j − K_jj}:
//     the joint bulk–surface state against its exact distribution (both engines).
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <functional>
#include <map>
#include <numeric>
#include <random>

#include "chem/chem_statistics.hpp"
#include "chem/chemistry_engine.hpp"
#include "chem/two_copies.hpp"
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

// The irregular 14-vertex patch, its interaction (μ₀/|C| = −strength k_BT on the mean
// cell, σ = 60 nm, a ramp potential) and caps; every state of up to `most` copies within the caps, with the
// log weight Π_j |C_j|^{N_j}/N_j! e^{−W − Σ V_j N_j} (|C| in units of the mean cell).
struct SmallPatch {
  SubvolumeGraph graph;
  ChemistryEngine::SurfaceInteraction interaction;
  double footprint = 0.0, mean_cell = 0.0;
  std::vector<std::vector<int>> states;
  std::vector<double> log_weight;

  // `strength`: −μ₀/|C| in k_BT for the mean cell (0: no pair terms). `onsite`: random
  // arrival energies a_j(m) in onsite_mean ± 1.5 k_BT, rows of 0–3 values (crowded
  // curvature sensing's form), F_j(N) = Σ_{m<N} a_j(min(m, row end)).
  SmallPatch(int most, double strength, bool onsite = false, double onsite_mean = 0.0) {
    const SurfaceMesh mesh = testing::irregularSmallPatch();
    graph = dualCellGraph(mesh).graph;
    const Index n = graph.count();
    for (double a : graph.size) mean_cell += a / static_cast<double>(n);
    const double range = 60.0, height = strength * mean_cell / (M_PI * range * range);
    std::vector<double> potential(static_cast<std::size_t>(n));
    for (Index v = 0; v < n; ++v) potential[v] = 0.008 * mesh.positions()[v][0];
    interaction = pairInteraction(graph, gaussianPairMoments(height, range), potential, DriftScheme::kExponential);
    if (onsite) {
      std::mt19937_64 random(41);
      std::uniform_real_distribution<double> energy(onsite_mean - 1.5, onsite_mean + 1.5);
      interaction.onsite_start = {0};
      for (Index v = 0; v < n; ++v) {
        const auto length = static_cast<int>(random() % 4);
        for (int m = 0; m < length; ++m) interaction.onsite.push_back(energy(random));
        interaction.onsite_start.push_back(static_cast<Index>(interaction.onsite.size()));
      }
    }
    footprint = mean_cell / 2.2;
    std::vector<int> cap(static_cast<std::size_t>(n)), N(static_cast<std::size_t>(n), 0);
    for (Index v = 0; v < n; ++v) cap[v] = static_cast<int>(std::floor(graph.size[v] / footprint));
    std::function<void(Index, int)> enumerate = [&](Index v, int left) {
      if (v == n) {
        states.push_back(N);
        return;
      }
      for (int c = 0; c <= std::min(left, cap[v]); ++c) {
        N[v] = c;
        enumerate(v + 1, left - c);
      }
      N[v] = 0;
    };
    enumerate(0, most);
    for (const auto& state : states) {
      double w = 0.0;
      for (Index j = 0; j < n; ++j) {
        w += state[j] * (std::log(graph.size[j] / mean_cell) - interaction.potential[j]) - std::lgamma(state[j] + 1.0);
        double r = interaction.self[j] * state[j];
        for (Index e = graph.start[j]; e < graph.start[j + 1]; ++e) r += interaction.pair[e] * state[graph.target[e]];
        w -= 0.5 * state[j] * r - 0.5 * interaction.self[j] * state[j];
        if (interaction.onsite_start.empty()) continue;
        const Index begin = interaction.onsite_start[j], end = interaction.onsite_start[j + 1];
        for (int m = 0; m < state[j] && begin < end; ++m) w -= interaction.onsite[std::min(begin + m, end - 1)];
      }
      log_weight.push_back(w);
    }
  }
  int copies(const std::vector<int>& state) const { return std::accumulate(state.begin(), state.end(), 0); }
  // Pearson's test of `samples` (indices into states) against weights exp(log_weight + extra).
  chemtest::ChiSquare fit(const std::vector<int>& samples, const std::function<double(std::size_t)>& extra) const {
    std::vector<double> p(states.size());
    double z = 0.0;
    for (std::size_t a = 0; a < states.size(); ++a) z += p[a] = std::exp(log_weight[a] + extra(a));
    return chemtest::goodnessOfFit(samples, [&](int a) { return a < static_cast<int>(p.size()) ? p[a] / z : 0.0; });
  }
};

// Samples the surface copies every `spacing` s as indices into the patch's states.
std::vector<int> sampleStates(ChemistryEngine& engine, const SmallPatch& patch, int count, double spacing) {
  std::map<std::vector<int>, int> index;
  for (std::size_t a = 0; a < patch.states.size(); ++a) index[patch.states[a]] = static_cast<int>(a);
  std::vector<int> samples;
  std::vector<int> N(static_cast<std::size_t>(patch.graph.count()));
  for (int s = 1; s <= count; ++s) {
    engine.advance(engine.time() + spacing);
    for (Index v = 0; v < patch.graph.count(); ++v) N[v] = engine.copies(engine.regionStart(1) + v, 1);
    const auto at = index.find(N);
    if (at == index.end()) {
      ADD_FAILURE() << "a state over the cap, or with copies lost";
      return samples;
    }
    samples.push_back(at->second);
  }
  return samples;
}

void expectJointStateFollowsTheEnergy(EngineKind kind, const SmallPatch& patch) {
  constexpr int kCopies = 3;
  ChemistryModel model;
  model.surfaces = {"patch"};
  model.species = {SpeciesDef{"G", 0.0}, SpeciesDef{"P", 1.0e6, 0, patch.footprint}};
  auto engine = makeChemistryEngine(kind, model, {0, 0}, 23);
  const auto n = static_cast<std::size_t>(patch.graph.count());
  const auto first = std::find_if(patch.states.begin(), patch.states.end(),
                                  [&](const std::vector<int>& state) { return patch.copies(state) == kCopies; });
  std::vector<int> start(2 * n, 0);
  for (std::size_t v = 0; v < n; ++v) start[2 * v + 1] = (*first)[v];
  engine->setSurface(0, patch.graph, std::vector<Index>(n, 0), start);
  engine->setSurfaceInteraction(1, patch.interaction);
  // ~10 relaxation times of the 200 nm patch at D = 1e6 nm²/s apart; only states with
  // all 3 copies on the surface can occur.
  const std::vector<int> samples = sampleStates(*engine, patch, 8000, 0.04);
  const chemtest::ChiSquare fit = patch.fit(samples, [&](std::size_t a) {
    return patch.copies(patch.states[a]) == kCopies ? 0.0 : -INFINITY;
  });
  EXPECT_GT(fit.p, 1e-3) << "chi2 " << fit.statistic << " on " << fit.dof << " dof";
}

TEST_P(PairStationary, JointStateFollowsThePairEnergy) { expectJointStateFollowsTheEnergy(GetParam(), SmallPatch(3, 1.0)); }

// On-site energies F_j(N_j) (crowded curvature sensing's exact form) beside the pair
// energy, and alone (no pair terms: the engine then recomputes only the ends' rates).
// Power: ignoring the on-site term in the hop rates fails both at χ² ≈ 15,000 on ~135 dof.
TEST_P(PairStationary, JointStateFollowsPairAndOnsiteEnergies) {
  expectJointStateFollowsTheEnergy(GetParam(), SmallPatch(3, 1.0, true));
}
TEST_P(PairStationary, JointStateFollowsAnOnsiteEnergyAlone) {
  expectJointStateFollowsTheEnergy(GetParam(), SmallPatch(3, 0.0, true));
}

// Binding from a bulk of 3 copies of G and unbinding at r e^{V_j + R_j − K_jj}: the joint
// state of bulk and surface is π(N) ∝ Π|C_j|^{N_j}/N_j! e^{−W − ΣVN} (k_on/(k_off V))^{ΣN}
// / n_G! (n_G = 3 − ΣN), with a stronger attraction (μ₀/|C| = −3 k_BT). Power:
// unbinding without the pair energy (plain r e^{βV}) fails at p ~ 1e-77 (nsm) and 1e-101 (direct).
void expectBindingFromABulkFollowsTheEnergy(EngineKind kind, const SmallPatch& patch) {
  constexpr int kCopies = 3;
  // k_on |C|/(k_off V) = 1/14 per mean cell: the surface as a whole weighs about as much
  // as the bulk, so the bound count responds to the pair energy.
  const double volume = 1e6, k_off = 20.0, k_on = k_off * volume / (14.0 * patch.mean_cell);  // nm³, 1/s, nm/s
  ChemistryModel model;
  model.volumes.size = {volume};
  model.volumes.start = {0, 0};
  model.surfaces = {"patch"};
  model.species = {SpeciesDef{"G", 0.0}, SpeciesDef{"P", 1.0e6, 0, patch.footprint}};
  model.addReactions("test", {parseReaction("G -> P", k_on, model.species), parseReaction("P -> G", k_off, model.species)});
  auto engine = makeChemistryEngine(kind, model, {kCopies, 0}, 29);
  const auto n = static_cast<std::size_t>(patch.graph.count());
  engine->setSurface(0, patch.graph, std::vector<Index>(n, 0), std::vector<int>(2 * n, 0));
  engine->setSurfaceInteraction(1, patch.interaction);
  // 0.2 s apart: ~4 unbinding times (the chain mixes through the bulk).
  const std::vector<int> samples = sampleStates(*engine, patch, 8000, 0.2);
  const chemtest::ChiSquare fit = patch.fit(samples, [&](std::size_t a) {
    const int bound = patch.copies(patch.states[a]);
    return -bound * std::log(14.0) - std::lgamma(kCopies - bound + 1.0);
  });
  EXPECT_GT(fit.p, 1e-3) << "chi2 " << fit.statistic << " on " << fit.dof << " dof";
}

TEST_P(PairStationary, BindingFromABulkFollowsThePairEnergy) {
  expectBindingFromABulkFollowsTheEnergy(GetParam(), SmallPatch(3, 3.0));
}
// Unbinding then also carries the on-site energy its copy leaves, a_j(N_j − 1); energies
// around +1 k_BT so that leaving it out shifts the bound count (fails at χ² ≈ 3,100 on 90 dof).
TEST_P(PairStationary, BindingFromABulkFollowsPairAndOnsiteEnergies) {
  expectBindingFromABulkFollowsTheEnergy(GetParam(), SmallPatch(3, 3.0, true, 1.0));
}

// Other reactions of an interacting species (dimerization on the membrane, thesis eq.
// 3.13) fire at mass action, and the field and hop rates follow the copies they change:
// after thousands of them the running engine's stored rates give the same total as a
// fresh engine built from its copies (relative 1e-12: sums in another order). Not
// updating the field after a reaction leaves stale rates (fails at 7e-4 relative).
TEST_P(PairStationary, ReactionsOfInteractingCopiesKeepTheFieldExact) {
  const SmallPatch patch(0, 1.0, true);
  ChemistryModel model;
  model.surfaces = {"patch"};
  // P hops rarely (~1 /s per copy), so stale rates would outlive the hops that refresh them.
  model.species = {SpeciesDef{"G", 0.0}, SpeciesDef{"P", 3.0e3, 0, patch.footprint}, SpeciesDef{"Q", 5.0e5, 0}};
  model.addReactions("test", {parseReaction("2 P -> Q", 2.0e5, model.species), parseReaction("Q -> 2 P", 200.0, model.species)});
  const auto n = static_cast<std::size_t>(patch.graph.count());
  std::vector<int> start(3 * n, 0);
  for (std::size_t v = 0; v < n; ++v) start[3 * v + 1] = v % 2;
  auto fresh = [&](const std::vector<int>& copies) {
    auto engine = makeChemistryEngine(GetParam(), model, {0, 0, 0}, 31);
    engine->setSurface(0, patch.graph, std::vector<Index>(n, 0), copies);
    engine->setSurfaceInteraction(1, patch.interaction);
    return engine;
  };
  auto engine = fresh(start);
  engine->advance(5.0);
  ASSERT_GT(engine->reactionEvents()[0], 500);
  std::vector<int> now(3 * n);
  for (std::size_t v = 0; v < n; ++v)
    for (Index s = 0; s < 3; ++s) now[3 * v + s] = engine->copies(engine->regionStart(1) + static_cast<Index>(v), s);
  const double running = engine->load().total, rebuilt = fresh(now)->load().total;
  EXPECT_NEAR(running, rebuilt, 1e-12 * rebuilt);
}

// Two species coupled by an attraction K^PQ (setSurfaceCoupling), one copy each on the
// patch, P in the ramp potential: the joint positions (p, q) follow
// |C_p||C_q| e^{−V_p − K^PQ_pq} (196 states). Power: leaving out the update of Q's rates
// when P hops (and of P's when Q hops) fails at χ² ≈ 1,120 on 160 dof.
TEST_P(PairStationary, TwoCoupledSpeciesFollowTheirCrossEnergy) {
  const SmallPatch patch(1, 0.0);
  const Index n = patch.graph.count();
  const PairKernel cross = pairKernel(patch.graph, gaussianPairMoments(2.0 * patch.mean_cell / (M_PI * 60.0 * 60.0), 60.0));
  ChemistryModel model;
  model.surfaces = {"patch"};
  model.species = {SpeciesDef{"G", 0.0}, SpeciesDef{"P", 1.0e6, 0}, SpeciesDef{"Q", 1.0e6, 0}};
  auto engine = makeChemistryEngine(GetParam(), model, {0, 0, 0}, 37);
  std::vector<int> start(3 * static_cast<std::size_t>(n), 0);
  start[3 * 0 + 1] = 1;
  start[3 * 5 + 2] = 1;
  engine->setSurface(0, patch.graph, std::vector<Index>(static_cast<std::size_t>(n), 0), start);
  engine->setSurfaceInteraction(1, patch.interaction);
  engine->setSurfaceInteraction(2, pairInteraction(patch.graph, PairMoments{}, std::vector<double>(static_cast<std::size_t>(n), 0.0),
                                                   DriftScheme::kExponential));
  engine->setSurfaceCoupling(1, 2, cross.self, cross.pair);
  EXPECT_THROW(engine->setSurfaceCoupling(2, 1, cross.self, cross.pair), std::invalid_argument);

  auto log_weight = [&](Index p, Index q) {
    double k = p == q ? cross.self[p] : 0.0;
    for (Index e = patch.graph.start[p]; e < patch.graph.start[p + 1]; ++e)
      if (patch.graph.target[e] == q) k = cross.pair[e];
    return std::log(patch.graph.size[p]) - patch.interaction.potential[p] + std::log(patch.graph.size[q]) - k;
  };
  const std::vector<int> samples = chemtest::sampleTwoCopies(*engine, n, 8000, 0.04);
  const chemtest::ChiSquare fit =
      chemtest::fitTwoCopies(samples, n, [&](Index p, Index q) { return std::exp(log_weight(p, q)); });
  EXPECT_GT(fit.p, 1e-3) << "chi2 " << fit.statistic << " on " << fit.dof << " dof";
}

INSTANTIATE_TEST_SUITE_P(BothEngines, PairStationary,
                         ::testing::Values(EngineKind::kNextSubvolume, EngineKind::kDirect),
                         [](const auto& info) { return info.param == EngineKind::kDirect ? "direct" : "nsm"; });

}  // namespace
}  // namespace cortex
