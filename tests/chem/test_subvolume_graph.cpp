// The engines on subvolume graphs that are not a grid (issue 9): free diffusion on a
// random graph with unequal sizes is stationary with copies proportional to size, and a
// surface species reacting with a 3D species of the compartment that holds its
// subvolume (S_surface + A_volume <-> C_surface) follows the exact master equation, also
// after the surface's subvolumes are replaced (a remesh) with the copies carried over.
// Both engines; fixed seeds; chi-square p > 1e-4.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "chem_models.hpp"
#include "chem_statistics.hpp"
#include "core/random.hpp"

namespace cortex {
namespace {

// A random connected graph: a random spanning tree plus extra edges, subvolume sizes in
// [0.5, 3] x 1e6 nm^3, a random conductance c_ij = c_ji per pair, and l^2_ij = size_i / c_ij
// (so size_i / l^2_ij is symmetric: detailed balance).
SubvolumeGraph randomGraph(Index n, int extra_edges, std::uint64_t seed) {
  RandomStream rng(seed, StreamId::kInitialConditions);
  std::vector<double> size(n);
  for (double& v : size) v = (0.5 + 2.5 * rng.uniform()) * 1e6;
  std::map<std::pair<Index, Index>, double> conductance;
  auto join = [&](Index i, Index j) {
    if (i == j) return;
    conductance.emplace(std::minmax(i, j), (0.2 + rng.uniform()) * 1e2);  // nm
  };
  for (Index i = 1; i < n; ++i) join(i, static_cast<Index>(rng.uniform() * i));
  for (int k = 0; k < extra_edges; ++k) join(static_cast<Index>(rng.uniform() * n), static_cast<Index>(rng.uniform() * n));
  std::vector<std::vector<std::pair<Index, double>>> out(n);
  for (const auto& [pair, c] : conductance) {
    out[pair.first].emplace_back(pair.second, c);
    out[pair.second].emplace_back(pair.first, c);
  }
  SubvolumeGraph g;
  g.size = size;
  for (Index i = 0; i < n; ++i) {
    for (const auto& [j, c] : out[i]) {
      g.target.push_back(j);
      g.hop_length2.push_back(size[i] / c);
    }
    g.start.push_back(static_cast<Index>(g.target.size()));
  }
  return g;
}

class SubvolumeGraphs : public ::testing::TestWithParam<EngineKind> {};

// 300 copies released in subvolume 0 of a 30-subvolume random graph. Hop rates D / l^2
// are 7-240 /s, so the slowest mode relaxes within a fraction of a second; samples 2 s
// apart are independent (lag-1 autocorrelation of one subvolume's count checked within 5
// standard errors of zero, 5 / sqrt(samples)). Pooled counts are then multinomial with
// p_i = size_i / total size.
TEST_P(SubvolumeGraphs, FreeDiffusionIsStationaryInProportionToSize) {
  ChemistryModel m;
  m.volumes = randomGraph(30, 25, 5);
  ASSERT_NO_THROW(validate(m.volumes, "random graph"));
  m.species.push_back({"A", 1.0e6});
  const Index n = m.volumes.count();
  std::vector<int> copies(n, 0);
  copies[0] = 300;
  auto engine = makeChemistryEngine(GetParam(), m, copies, 31);
  engine->advance(10.0);
  const int samples = 250;
  std::vector<double> counts(n, 0.0);
  std::vector<int> first;
  for (int k = 0; k < samples; ++k) {
    engine->advance(engine->time() + 2.0);
    for (Index i = 0; i < n; ++i) counts[i] += engine->copies(i, 0);
    first.push_back(engine->copies(0, 0));
  }
  EXPECT_LT(std::abs(chemtest::lagOneCorrelation(first)), 5.0 / std::sqrt(samples));
  double total_size = 0.0;
  for (double v : m.volumes.size) total_size += v;
  double chi2 = 0.0;
  for (Index i = 0; i < n; ++i) {
    const double expected = 300.0 * samples * m.volumes.size[i] / total_size;
    chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
  }
  const double p = chemtest::chiSquarePValue(chi2, n - 1);
  std::printf("[ measured ] %s: chi2 %.1f on %d dof, p = %.3g\n", chemtest::engineName(GetParam()), chi2, n - 1, p);
  EXPECT_GT(p, 1e-4);
}

// --- S_surface + A_volume <-> C_surface against the master equation ---------------------

// Two compartments (0.8 and 1.3 fL) with A hopping between them; a surface of subvolumes
// (areas given) each held by one compartment, S hopping between neighbours; per surface
// subvolume j: S + A -> C at k_f s_j a_h(j) / V_h(j) (thesis eq. 3.13: k A [S][A]) and
// C -> S + A at k_b c_j. Three A and two S copies, so the state space is small.
struct Coupled {
  // Binding 2-4 /s per S at the start, unbinding 2 /s: both matter from the first moment.
  static constexpr double kF = 6.0e8, kB = 2.0;  // nm^3/s, 1/s
  ChemistryModel model;
  SubvolumeGraph surface;
  std::vector<Index> holders;

  explicit Coupled(std::vector<double> areas, std::vector<Index> held_by) : holders(std::move(held_by)) {
    model.volumes = SubvolumeGraph{};
    model.volumes.size = {0.8e9, 1.3e9};
    model.volumes.start = {0, 1, 2};
    model.volumes.target = {1, 0};
    model.volumes.hop_length2 = {0.8e9 / 5e5, 1.3e9 / 5e5};  // conductance 5e5 nm: A hops at D / l^2
    model.surfaces = {"membrane"};
    model.species = {{"A", 2.0e3, -1}, {"S", 20.0, 0}, {"C", 0.0, 0}};  // A hops ~1.5 /s, S ~3 /s
    model.addReactions("test", {parseReaction("S + A -> C", kF, model.species),
                                parseReaction("C -> S + A", kB, model.species)});
    // A path of surface subvolumes, conductance 50 (dimensionless on a surface).
    surface.size = std::move(areas);
    const auto n = static_cast<Index>(surface.size.size());
    for (Index j = 0; j < n; ++j) {
      for (Index k : {j - 1, j + 1}) {
        if (k < 0 || k >= n) continue;
        surface.target.push_back(k);
        surface.hop_length2.push_back(surface.size[j] / 50.0);
      }
      surface.start.push_back(static_cast<Index>(surface.target.size()));
    }
  }
  Index surfaceCount() const { return surface.count(); }
};

// States (a_0, a_1, s_j..., c_j...) with sum a + sum c = 3 and sum s + sum c = 2, their
// generator, and p(t) by uniformization.
class MasterEquation {
 public:
  explicit MasterEquation(const Coupled& sys) : sys_(sys), n_(sys.surfaceCount()) {
    enumerate(std::vector<int>(2 + 2 * n_, 0), 0);
    for (std::size_t k = 0; k < states_.size(); ++k) index_[states_[k]] = static_cast<int>(k);
    const double d_a = sys.model.species[0].diffusion, d_s = sys.model.species[1].diffusion;
    rates_.assign(states_.size(), {});
    for (std::size_t k = 0; k < states_.size(); ++k) {
      const std::vector<int>& x = states_[k];
      auto to = [&](std::vector<int> y, double rate) {
        if (rate > 0) rates_[k].emplace_back(index_.at(y), rate);
      };
      for (int i = 0; i < 2; ++i) {
        std::vector<int> y = x;
        --y[i], ++y[1 - i];
        to(y, x[i] * d_a / sys.model.volumes.hop_length2[i]);
      }
      for (Index j = 0; j < n_; ++j) {
        for (Index e = sys.surface.start[j]; e < sys.surface.start[j + 1]; ++e) {
          std::vector<int> y = x;
          --y[2 + j], ++y[2 + sys.surface.target[e]];
          to(y, x[2 + j] * d_s / sys.surface.hop_length2[e]);
        }
        const Index h = sys.holders[j];
        std::vector<int> bind = x, unbind = x;
        --bind[2 + j], --bind[h], ++bind[2 + n_ + j];
        to(bind, Coupled::kF * x[2 + j] * x[h] / sys.model.volumes.size[h]);
        ++unbind[2 + j], ++unbind[h], --unbind[2 + n_ + j];
        to(unbind, Coupled::kB * x[2 + n_ + j]);
      }
    }
  }

  std::size_t size() const { return states_.size(); }
  int indexOf(const std::vector<int>& x) const { return index_.at(x); }

  // p(t) from p(0) = delta(start).
  std::vector<double> at(const std::vector<int>& start, double t) const {
    double lambda = 0.0;
    for (const auto& out : rates_) {
      double sum = 0.0;
      for (const auto& [k, r] : out) sum += r;
      lambda = std::max(lambda, sum);
    }
    lambda *= 1.05;
    std::vector<double> p(size(), 0.0), term(size(), 0.0), result(size(), 0.0);
    p[indexOf(start)] = 1.0;
    // sum_k Poisson(k; lambda t) P^k p, P = I + Q / lambda.
    double weight = std::exp(-lambda * t), cumulative = 0.0;
    for (int k = 0; cumulative < 1.0 - 1e-13; ++k) {
      if (k > 0) weight *= lambda * t / k;
      cumulative += weight;
      for (std::size_t s = 0; s < size(); ++s) result[s] += weight * p[s];
      std::fill(term.begin(), term.end(), 0.0);
      for (std::size_t s = 0; s < size(); ++s) {
        double out = 0.0;
        for (const auto& [to, r] : rates_[s]) {
          term[to] += p[s] * r / lambda;
          out += r;
        }
        term[s] += p[s] * (1.0 - out / lambda);
      }
      p.swap(term);
    }
    return result;
  }

 private:
  // x = (a0, a1, s..., c...) with the two conservation laws.
  void enumerate(std::vector<int> x, std::size_t slot) {
    if (slot == x.size()) {
      int a = x[0] + x[1], s = 0, c = 0;
      for (Index j = 0; j < n_; ++j) s += x[2 + j], c += x[2 + n_ + j];
      if (a + c == 3 && s + c == 2) states_.push_back(x);
      return;
    }
    for (int v = 0; v <= 3; ++v) {
      x[slot] = v;
      enumerate(x, slot + 1);
    }
  }

  const Coupled& sys_;
  Index n_;
  std::vector<std::vector<int>> states_;
  std::map<std::vector<int>, int> index_;
  std::vector<std::vector<std::pair<int, double>>> rates_;
};

// Engine state as a master-equation state vector.
std::vector<int> stateOf(const ChemistryEngine& e, Index surface_count) {
  std::vector<int> x{e.copies(0, 0), e.copies(1, 0)};
  const Index first = e.regionStart(1);
  for (Index j = 0; j < surface_count; ++j) x.push_back(e.copies(first + j, 1));
  for (Index j = 0; j < surface_count; ++j) x.push_back(e.copies(first + j, 2));
  return x;
}

std::vector<int> surfaceCopies(Index species, const std::vector<int>& s, const std::vector<int>& c) {
  std::vector<int> out(s.size() * static_cast<std::size_t>(species), 0);
  for (std::size_t j = 0; j < s.size(); ++j) {
    out[j * species + 1] = s[j];
    out[j * species + 2] = c[j];
  }
  return out;
}

void expectDistribution(const std::vector<int>& observed, const std::vector<double>& exact, const char* what) {
  const chemtest::ChiSquare fit = chemtest::goodnessOfFit(
      observed, [&](int k) { return k < static_cast<int>(exact.size()) ? exact[k] : 0.0; });
  std::printf("[ measured ] %s: chi2 %.1f on %d dof, p = %.3g\n", what, fit.statistic, fit.dof, fit.p);
  EXPECT_GT(fit.p, 1e-4) << what;
}

// Independent runs from one start (A: 3 in compartment 0; S: 2 on surface subvolume 0)
// compared with the exact p(t) at an early time (0.3 s, far from equilibrium: binding
// and hops have each happened about once) and a late one; then the surface is replaced
// by a finer one (three subvolumes, held by both compartments) with the copies carried
// over, and the state 1 s later compared with the master equation of the new surface.
TEST_P(SubvolumeGraphs, SurfaceVolumeReactionFollowsTheMasterEquation) {
  const Coupled before({300.0, 500.0}, {0, 1});
  const Coupled after({200.0, 250.0, 350.0}, {0, 1, 1});
  const MasterEquation exact(before), exact_after(after);
  ASSERT_EQ(exact.size(), 30u);
  const std::vector<int> start{3, 0, 2, 0, 0, 0};
  const std::vector<double> p_early = exact.at(start, 0.3), p_late = exact.at(start, 3.0);
  const int runs = GetParam() == EngineKind::kDirect ? 8000 : 20000;
  std::vector<int> early, late, remeshed;
  std::vector<double> p_remeshed(exact_after.size(), 0.0);
  std::vector<std::vector<int>> late_states;
  const auto species = static_cast<Index>(before.model.species.size());
  for (int run = 0; run < runs; ++run) {
    auto engine = makeChemistryEngine(GetParam(), before.model, {3, 0, 0, 0, 0, 0}, 1000 + run);
    engine->setSurface(0, before.surface, before.holders, surfaceCopies(species, {2, 0}, {0, 0}));
    engine->advance(0.3);
    early.push_back(exact.indexOf(stateOf(*engine, 2)));
    engine->advance(3.0);
    const std::vector<int> x = stateOf(*engine, 2);
    late.push_back(exact.indexOf(x));
    // Remesh: subvolume 0 keeps its copies, subvolume 1's go to the new 1 (S) and 2 (C).
    engine->setSurface(0, after.surface, after.holders, surfaceCopies(species, {x[2], x[3], 0}, {x[4], 0, x[5]}));
    const std::vector<int> carried = stateOf(*engine, 3);
    ASSERT_EQ(carried[0] + carried[1], x[0] + x[1]) << "3D copies must not change";
    // The exact p(4 s) after the remesh, averaged over the carried states.
    const std::vector<double> p = exact_after.at(carried, 1.0);
    for (std::size_t s = 0; s < p.size(); ++s) p_remeshed[s] += p[s] / runs;
    engine->advance(4.0);
    remeshed.push_back(exact_after.indexOf(stateOf(*engine, 3)));
  }
  const char* name = chemtest::engineName(GetParam());
  expectDistribution(early, p_early, (std::string(name) + " at 0.3 s").c_str());
  expectDistribution(late, p_late, (std::string(name) + " at 3 s").c_str());
  expectDistribution(remeshed, p_remeshed, (std::string(name) + " 1 s after the remesh").c_str());
}

INSTANTIATE_TEST_SUITE_P(BothEngines, SubvolumeGraphs,
                         ::testing::Values(EngineKind::kNextSubvolume, EngineKind::kDirect),
                         [](const auto& info) { return chemtest::engineName(info.param); });

}  // namespace
}  // namespace cortex
