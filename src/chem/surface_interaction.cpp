// EngineBase's pair interactions of surface species (ChemistryEngine::SurfaceInteraction):
// the field R = K N of the other copies and the hop rates it biases, kept exact after
// every event that moves a copy.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "chem/engine_base.hpp"

namespace cortex {
namespace {

bool finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// Throws std::invalid_argument unless K (`self` per subvolume, `pair` per directed edge of
// g) has those sizes, finite values and K_jk = K_kj. `what`: "an interaction", "a coupling".
void checkKernel(const SubvolumeGraph& g, const std::vector<double>& self, const std::vector<double>& pair,
                 const std::string& what) {
  if (self.size() != static_cast<std::size_t>(g.count()) || pair.size() != static_cast<std::size_t>(g.numEdges()))
    throw std::invalid_argument("chemistry engine: " + what + " needs a self term per subvolume and a pair term "
                                "per edge of the surface");
  if (!finite(self) || !finite(pair)) throw std::invalid_argument("chemistry engine: " + what + "'s term is not finite");
  for (Index i = 0; i < g.count(); ++i)
    for (Index e = g.start[i]; e < g.start[i + 1]; ++e) {
      const Index back = reverseEdge(g, i, e);
      if (back < 0 || std::abs(pair[e] - pair[back]) > 1e-12 * std::max(std::abs(pair[e]), 1.0))
        throw std::invalid_argument("chemistry engine: " + what + "'s pair terms are not symmetric");
    }
}

}  // namespace

void EngineBase::setSurfaceInteraction(Index species, SurfaceInteraction interaction) {
  if (species < 0 || species >= S_) throw std::out_of_range("chemistry engine: no species " + std::to_string(species));
  const Index region = net_.speciesRegion[species];
  if (region == 0) throw std::invalid_argument("chemistry engine: only surface species interact");
  std::vector<Index> unbinds, binds;
  for (Index r = 0; r < R_; ++r) {
    int own = 0, others = 0;
    for (const SpeciesChange& change : net_.changes[r]) {
      if (change.species == species) own = change.delta;
      else if (!change.held) ++others;
    }
    if (own == 1 && others == 0) binds.push_back(r);  // an adsorption of one copy
    if (own >= 0 || others > 0) continue;  // not a desorption: mass action
    const ReactionKernel& k = net_.kernels[r];
    if (k.kind != ReactionKernel::Kind::kLinear || k.a != species || own != -1)
      throw std::invalid_argument("chemistry engine: interacting species \"" + species_[species].name +
                                  "\" leaves the surface in reaction \"" + equations_[r] +
                                  "\": only one copy at a time may unbind (its energy factor is per copy)");
    unbinds.push_back(r);
  }
  const SubvolumeGraph& g = graphs_[region];
  const auto n = static_cast<std::size_t>(g.count());
  checkKernel(g, interaction.self, interaction.pair, "an interaction");
  if (interaction.potential.size() != n)
    throw std::invalid_argument("chemistry engine: an interaction needs a potential per subvolume of the surface");
  if (!finite(interaction.potential) || !finite(interaction.onsite))
    throw std::invalid_argument("chemistry engine: an interaction term is not finite");
  const std::vector<Index>& row = interaction.onsite_start;
  const bool rows_ok = row.empty() ? interaction.onsite.empty()
                                   : row.size() == n + 1 && row.front() == 0 &&
                                         row.back() == static_cast<Index>(interaction.onsite.size()) &&
                                         std::is_sorted(row.begin(), row.end());
  if (!rows_ok) throw std::invalid_argument("chemistry engine: an interaction's on-site rows are not laid out per subvolume");
  drift_[species].clear();
  interaction_[species] = std::move(interaction);
  field_[species].assign(n, 0.0);
  interacts_[species] = 1;
  paired_[species] = !couplings_[species].empty();
  for (const std::vector<double>* terms : {&interaction_[species].self, &interaction_[species].pair})
    for (double x : *terms) paired_[species] = paired_[species] || x != 0.0;
  if (!unbinds.empty() && unbinding_.empty()) unbinding_.assign(R_, -1);
  for (Index r : unbinds) unbinding_[r] = species;
  if (!binds.empty() && binding_.empty()) binding_.assign(R_, -1);
  for (Index r : binds) binding_[r] = species;
  computeHopRates();
  for (Index i = region_start_[region]; i < region_start_[region + 1]; ++i) refreshSubvolume(i);
}

void EngineBase::setSurfaceCoupling(Index a, Index b, std::vector<double> self, std::vector<double> pair) {
  for (Index s : {a, b})
    if (s < 0 || s >= S_ || !interacting(s))
      throw std::invalid_argument("chemistry engine: a coupling needs two species with an interaction");
  const Index region = net_.speciesRegion[a];
  if (a == b || net_.speciesRegion[b] != region)
    throw std::invalid_argument("chemistry engine: a coupling needs two different species of one surface");
  for (const Coupling& c : couplings_[a])
    if (c.other == b)
      throw std::invalid_argument("chemistry engine: species \"" + species_[a].name + "\" and \"" +
                                  species_[b].name + "\" are coupled twice");
  checkKernel(graphs_[region], self, pair, "a coupling");
  couplings_[a].push_back({b, self, pair});
  couplings_[b].push_back({a, std::move(self), std::move(pair)});
  paired_[a] = paired_[b] = 1;
  computeHopRates();
  for (Index i = region_start_[region]; i < region_start_[region + 1]; ++i) refreshSubvolume(i);
}

double EngineBase::leavingEnergy(Index i, Index s, int added) const {
  const SurfaceInteraction& k = interaction_[s];
  const Index a = i - region_start_[net_.speciesRegion[s]];
  const int n = copies_[static_cast<std::size_t>(i) * S_ + s] + added;
  // The field counts every copy in i, the leaving one's self term K_ii included.
  return k.potential[a] + field_[s][a] + (added - 1) * k.self[a] + arrivalEnergy(s, a, std::max(n - 1, 0));
}

double EngineBase::unbindingFactor(Index i, Index s) const {
  return std::exp(std::min(leavingEnergy(i, s, 0), kLargestUnbindingEnergy));
}

bool EngineBase::energyAccepts(Index r, Index i) {
  if (binding_.empty() || binding_[r] < 0) return true;
  const double excess = leavingEnergy(i, binding_[r], 1) - kLargestUnbindingEnergy;
  return !(excess > 0.0) || rng_.uniform() < std::exp(-excess);
}

double EngineBase::arrivalEnergy(Index s, Index a, int m) const {
  const SurfaceInteraction& k = interaction_[s];
  if (k.onsite_start.empty()) return 0.0;
  const Index begin = k.onsite_start[a], end = k.onsite_start[a + 1];
  if (begin == end) return 0.0;
  return k.onsite[std::min<Index>(begin + m, end - 1)];
}

double EngineBase::pairField(Index s, Index i) const {
  const SurfaceInteraction& k = interaction_[s];
  const Index first = region_start_[net_.speciesRegion[s]];
  const Index first_edge = edge_start_[first];
  auto field = [&](const std::vector<double>& self, const std::vector<double>& pair, Index of) {
    double r = self[i - first] * copies_[static_cast<std::size_t>(i) * S_ + of];
    for (Index e = edge_start_[i]; e < edge_start_[i + 1]; ++e)
      r += pair[e - first_edge] * copies_[static_cast<std::size_t>(edge_target_[e]) * S_ + of];
    return r;
  };
  double r = field(k.self, k.pair, s);
  for (const Coupling& c : couplings_[s]) r += field(c.self, c.pair, c.other);
  return r;
}

EngineBase::InteractionView EngineBase::interactionView(Index s) const {
  const SurfaceInteraction& k = interaction_[s];
  const Index first = region_start_[net_.speciesRegion[s]];
  return {k.potential.data(), k.self.data(), k.pair.data(), field_[s].data(), !k.onsite_start.empty(),
          species_[s].diffusion, s, first, edge_start_[first], k.scheme == DriftScheme::kExponential};
}

double EngineBase::interactionRate(const InteractionView& w, Index i, Index e) const {
  const Index j = edge_target_[e];
  const Index a = i - w.first, b = j - w.first;
  // The moving copy leaves its own field behind: − K_ik + K_ii.
  double x = w.potential[b] - w.potential[a] + w.field[b] - w.field[a] - w.pair[e - w.first_edge] + w.self[a];
  if (w.onsite) {
    const int n_from = copies_[static_cast<std::size_t>(i) * S_ + w.species];
    const int n_to = copies_[static_cast<std::size_t>(j) * S_ + w.species];
    x += arrivalEnergy(w.species, b, n_to) - arrivalEnergy(w.species, a, std::max(n_from - 1, 0));
  }
  const double factor = w.exponential ? exponentialDrift(x) : linearDrift(x, -x);
  return w.diffusion / hop_length2_[e] * factor;
}

void EngineBase::computeInteractionRates(const InteractionView& w, Index i) {
  double total = 0.0;
  for (Index e = edge_start_[i]; e < edge_start_[i + 1]; ++e) {
    const double rate = interactionRate(w, i, e);
    edge_rate_[static_cast<std::size_t>(e) * S_ + w.species] = rate;
    total += rate;
  }
  hop_out_[static_cast<std::size_t>(i) * S_ + w.species] = total;
}

// R changes at a, b and their neighbours (K has the graph's sparsity), for s and for the
// species coupled to it: every rate of theirs out of those changes. A vertex one ring
// further keeps its own R, so only its edges into them change; its hopOut is summed anew
// from the stored edge rates (in edge order, so it is the same number computeHopRates
// gives).
const std::vector<Index>& EngineBase::interactionChanged(Index s, Index a, Index b) {
  if (mark_.size() != static_cast<std::size_t>(N_) || mark_round_ >= UINT32_MAX - 2) {
    mark_.assign(N_, 0);
    mark_round_ = 0;
  }
  const std::uint32_t near_mark = ++mark_round_, reach_mark = ++mark_round_;
  near_.clear();
  auto add = [&](std::vector<Index>& list, Index v, std::uint32_t mark) {
    if (mark_[v] == near_mark || mark_[v] == mark) return;
    mark_[v] = mark;
    list.push_back(v);
  };
  // Without pair terms only the ends' own (on-site) energies changed.
  for (Index end : {a, b}) {
    add(near_, end, near_mark);
    if (paired_[s])
      for (Index e = edge_start_[end]; e < edge_start_[end + 1]; ++e) add(near_, edge_target_[e], near_mark);
  }
  reach_ = near_;
  for (Index v : near_)
    for (Index e = edge_start_[v]; e < edge_start_[v + 1]; ++e) add(reach_, edge_target_[e], reach_mark);
  // The fields that read copies of s: its own and those of the species coupled to it.
  const Index first = region_start_[net_.speciesRegion[s]];
  auto update = [&](Index u) {
    for (Index v : near_) field_[u][v - first] = pairField(u, v);
    const InteractionView w = interactionView(u);
    for (Index v : near_) computeInteractionRates(w, v);
    for (auto k = near_.size(); k < reach_.size(); ++k) {
      const Index v = reach_[k];
      double total = 0.0;
      for (Index e = edge_start_[v]; e < edge_start_[v + 1]; ++e) {
        double& rate = edge_rate_[static_cast<std::size_t>(e) * S_ + u];
        if (mark_[edge_target_[e]] == near_mark) rate = interactionRate(w, v, e);
        total += rate;
      }
      hop_out_[static_cast<std::size_t>(v) * S_ + u] = total;
    }
  };
  update(s);
  for (const Coupling& c : couplings_[s]) update(c.other);
  return reach_;
}

}  // namespace cortex
