#include "chem/engine_base.hpp"

#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"

namespace cortex {

EngineBase::EngineBase(const ChemistryModel& model, const std::vector<int>& copies, std::uint64_t seed)
    : net_(model),
      species_(model.species),
      S_(net_.numSpecies),
      R_(net_.numReactions),
      rng_(seed, StreamId::kChemistry),
      reaction_events_(net_.numReactions, 0),
      graphs_(model.surfaces.size() + 1),
      holders_(model.surfaces.size() + 1),
      hooks_(R_, nullptr),
      ranges_(model.ranges),
      claimed_(ranges_.size(), 0),
      weighted_(S_, 0),
      hop_rate_(S_, 0.0),
      confined_(S_, 0),
      scale_species_(R_, -1),
      drift_(S_),
      interaction_(S_),
      field_(S_),
      interacts_(S_, 0),
      paired_(S_, 0),
      couplings_(S_) {
  for (const ReactionDef& r : model.reactions) equations_.push_back(r.equation);
  aggregated_slot_.assign(R_, -1);
  for (Index r = 0; r < R_; ++r)
    if (aggregated(r)) {
      aggregated_slot_[r] = static_cast<Index>(aggregated_.size());
      aggregated_.push_back(r);
    }
  site_weight_.resize(aggregated_.size());
  graphs_[0] = model.volumes;
  const Index n0 = model.volumes.count();
  if (copies.size() != static_cast<std::size_t>(n0) * S_)
    throw std::invalid_argument("chemistry engine: " + std::to_string(copies.size()) + " initial copies for " +
                                std::to_string(n0) + " subvolumes x " + std::to_string(S_) + " species");
  for (std::size_t i = 0; i < copies.size(); ++i) {
    if (copies[i] < 0)
      throw InputError("chemistry: negative initial copies of species \"" + model.species[i % S_].name +
                       "\" in subvolume " + std::to_string(i / S_));
    if (copies[i] > 0 && net_.speciesRegion[i % S_] != 0)
      throw std::invalid_argument("chemistry engine: surface species \"" + model.species[i % S_].name +
                                  "\" given copies in a 3D subvolume");
  }
  layOut(0, copies);
}

void EngineBase::layOut(Index replaced, const std::vector<int>& fresh) {
  const auto regions = static_cast<Index>(graphs_.size());
  std::vector<Index> start(regions + 1, 0);
  for (Index k = 0; k < regions; ++k) start[k + 1] = start[k] + graphs_[k].count();
  const Index n = start[regions];
  std::vector<int> copies(static_cast<std::size_t>(n) * S_, 0);
  std::vector<double> factor(static_cast<std::size_t>(n) * R_, 1.0);
  for (Index k = 0; k < regions; ++k) {
    const Index count = graphs_[k].count();
    if (k == replaced) {
      std::copy(fresh.begin(), fresh.end(), copies.begin() + static_cast<std::ptrdiff_t>(start[k]) * S_);
    } else if (!region_start_.empty()) {
      const Index old = region_start_[k];
      std::copy_n(copies_.begin() + static_cast<std::ptrdiff_t>(old) * S_, static_cast<std::size_t>(count) * S_,
                  copies.begin() + static_cast<std::ptrdiff_t>(start[k]) * S_);
      std::copy_n(factor_.begin() + static_cast<std::ptrdiff_t>(old) * R_, static_cast<std::size_t>(count) * R_,
                  factor.begin() + static_cast<std::ptrdiff_t>(start[k]) * R_);
    }
  }
  copies_ = std::move(copies);
  factor_ = std::move(factor);
  region_start_ = std::move(start);
  N_ = n;

  region_of_.assign(n, 0);
  size_.assign(n, 0.0);
  holder_.assign(n, 0);
  edge_start_.assign(1, 0);
  edge_target_.clear();
  hop_length2_.clear();
  for (Index k = 0; k < regions; ++k) {
    const SubvolumeGraph& g = graphs_[k];
    const Index first = region_start_[k];
    for (Index i = 0; i < g.count(); ++i) {
      region_of_[first + i] = k;
      size_[first + i] = g.size[i];
      holder_[first + i] = k == 0 ? i : holders_[k][i];
      for (Index e = g.start[i]; e < g.start[i + 1]; ++e) {
        edge_target_.push_back(first + g.target[e]);
        hop_length2_.push_back(g.hop_length2[e]);
      }
      edge_start_.push_back(static_cast<Index>(edge_target_.size()));
    }
  }
  // Surface subvolumes by holder, in subvolume order (none held by a surface subvolume).
  std::vector<std::vector<Index>> held(n);
  for (Index i = region_start_[1]; i < n; ++i) held[holder_[i]].push_back(i);
  held_ = Rows<Index>{};
  for (const auto& row : held) {
    held_.values.insert(held_.values.end(), row.begin(), row.end());
    held_.endRow();
  }
  room_.clear();
  crowding_.assign(regions, {});
  for (Index s = 0; s < S_; ++s)
    if (species_[s].footprint > 0.0) crowding_[net_.speciesRegion[s]].push_back(s);
  for (Index k = 0; k < regions; ++k) {
    if (crowding_[k].empty()) continue;
    if (room_.empty()) room_.assign(static_cast<std::size_t>(n), 0.0);
    for (Index i = region_start_[k]; i < region_start_[k + 1]; ++i) room_[i] = crowdingRoom(size_[i]);
  }
  diffusing_.assign(regions, {});
  for (Index s = 0; s < S_; ++s)
    if (species_[s].diffusion > 0.0) diffusing_[net_.speciesRegion[s]].push_back(s);
  computeHopRates();
}

void EngineBase::refreshBindingWeight(Index h, Index r) {
  std::vector<double>& w = site_weight_[aggregated_slot_[r]];
  if (w.size() != held_.values.size()) w.assign(held_.values.size(), 0.0);
  double sum = 0.0;
  for (Index k = held_.start[h]; k < held_.start[h + 1]; ++k) sum += w[k] = bindingWeight(held_.values[k], r);
  binding_weight_[static_cast<std::size_t>(h) * R_ + r] = sum;
}

void EngineBase::refreshBindingWeights(Index h) {
  if (aggregated_.empty()) return;
  if (binding_weight_.size() != static_cast<std::size_t>(region_start_[1]) * R_)
    binding_weight_.assign(static_cast<std::size_t>(region_start_[1]) * R_, 0.0);
  for (Index r : aggregated_) refreshBindingWeight(h, r);
}

Index EngineBase::drawBindingSite(Index h, Index r) {
  const std::vector<double>& w = site_weight_[aggregated_slot_[r]];
  double x = rng_.uniform() * binding_weight_[static_cast<std::size_t>(h) * R_ + r];
  Index last = -1;
  for (Index k = held_.start[h]; k < held_.start[h + 1]; ++k) {
    if (!(w[k] > 0.0)) continue;
    last = held_.values[k];
    if (x < w[k]) return last;
    x -= w[k];
  }
  return last;  // rounding at the end
}

// Unweighted species hop at D / l^2 along every edge of their region (all edges alike);
// the others get per-edge rates, scaled by a / f_source when confined.
void EngineBase::computeHopRates() {
  const auto regions = static_cast<Index>(graphs_.size());
  std::vector<char> uniform(regions, 1);
  for (Index k = 0; k < regions; ++k) {
    const auto& l2 = graphs_[k].hop_length2;
    for (double v : l2) uniform[k] = uniform[k] && v == l2.front();
  }
  bool any_weighted = false;
  for (Index s = 0; s < S_; ++s) {
    const Index k = net_.speciesRegion[s];
    weighted_[s] = confined_[s] || !uniform[k] || !drift_[s].empty() || interacting(s);
    any_weighted = any_weighted || weighted_[s];
    const auto& l2 = graphs_[k].hop_length2;
    hop_rate_[s] = l2.empty() ? 0.0 : species_[s].diffusion / l2.front();
  }
  hop_out_.clear();
  edge_rate_.clear();
  if (!any_weighted) return;
  hop_out_.assign(static_cast<std::size_t>(N_) * S_, 0.0);
  edge_rate_.assign(edge_target_.size() * S_, 0.0);
  for (Index s = 0; s < S_; ++s) {
    if (!weighted_[s]) continue;
    const Index k = net_.speciesRegion[s];
    if (interacting(s)) {
      for (Index i = region_start_[k]; i < region_start_[k + 1]; ++i) field_[s][i - region_start_[k]] = pairField(s, i);
      for (Index i = region_start_[k]; i < region_start_[k + 1]; ++i) computeInteractionRates(s, i);
      continue;
    }
    const Index first_edge = edge_start_[region_start_[k]];
    for (Index i = region_start_[k]; i < region_start_[k + 1]; ++i) {
      double total = 0.0;
      for (Index e = edge_start_[i]; e < edge_start_[i + 1]; ++e) {
        double rate = species_[s].diffusion / hop_length2_[e];
        if (!drift_[s].empty()) rate *= drift_[s][e - first_edge];
        if (confined_[s]) {
          const double f = volume_[static_cast<std::size_t>(i) * S_ + s];
          const bool open = f > 0.0 && volume_[static_cast<std::size_t>(edge_target_[e]) * S_ + s] > 0.0;
          rate = open ? rate * edge_fraction_[static_cast<std::size_t>(e) * S_ + s] / f : 0.0;
        }
        edge_rate_[static_cast<std::size_t>(e) * S_ + s] = rate;
        total += rate;
      }
      hop_out_[static_cast<std::size_t>(i) * S_ + s] = total;
    }
  }
}

double EngineBase::heldScale(Index i, Index r) const {
  if (volume_.empty() || net_.region[r] != region_of_[i]) return 1.0;
  const std::size_t h = static_cast<std::size_t>(holder_[i]) * S_;
  double scale = 1.0;
  for (const SpeciesChange& c : net_.changes[r])
    if (c.held && !(volume_[h + c.species] > 0.0)) return 0.0;
  const ReactionKernel& k = net_.kernels[r];
  if (k.kind != ReactionKernel::Kind::kConstant && k.a_held) {
    const double f = volume_[h + k.a];
    if (!(f > 0.0)) return 0.0;
    scale /= k.kind == ReactionKernel::Kind::kDimer ? f * f : f;
  }
  if (k.kind == ReactionKernel::Kind::kPair && k.b_held) {
    const double f = volume_[h + k.b];
    if (!(f > 0.0)) return 0.0;
    scale /= f;
  }
  return scale;
}

std::size_t EngineBase::slot(Index subvolume, Index species) const {
  if (subvolume < 0 || subvolume >= N_ || species < 0 || species >= S_)
    throw std::out_of_range("chemistry engine: no species " + std::to_string(species) + " in subvolume " +
                            std::to_string(subvolume));
  return static_cast<std::size_t>(subvolume) * S_ + species;
}

void EngineBase::checkCopies(Index subvolume, Index species, int n) const {
  slot(subvolume, species);
  if (n < 0) throw std::invalid_argument("chemistry engine: negative copy number " + std::to_string(n));
  if (n > 0 && !active(subvolume, species))
    throw std::invalid_argument("chemistry engine: subvolume " + std::to_string(subvolume) +
                                " cannot hold species " + std::to_string(species) +
                                " (another region, or no volume on its side of its membrane)");
}

void EngineBase::growthOverflow(Index subvolume, Index species, Index reaction) const {
  const std::string where = region_of_[subvolume] == 0 ? fmt::format("compartment {}", subvolume)
                                                        : fmt::format("surface subvolume {}", subvolume);
  throw RunError(fmt::format("chemistry: reaction \"{}\" would take the copies of \"{}\" in {} past 2^31 - 1, "
                             "the most a copy number holds (a reaction network growing without bound, or a "
                             "stoichiometry too large?)",
                             equations_[reaction], species_[species].name, where));
}

void EngineBase::checkRateFactor(Index reaction, Index subvolume, double factor) const {
  if (reaction < 0 || reaction >= R_ || subvolume < 0 || subvolume >= N_)
    throw std::out_of_range("chemistry engine: no reaction " + std::to_string(reaction) + " in subvolume " +
                            std::to_string(subvolume));
  if (!std::isfinite(factor) || factor < 0.0)
    throw std::invalid_argument("chemistry engine: rate factor must be finite and >= 0, got " + std::to_string(factor));
}

RateFactors EngineBase::claimRateFactors(const ReactionRange& range) {
  for (std::size_t k = 0; k < ranges_.size(); ++k) {
    // The owner tells apart two empty ranges at the same place (a model without
    // reactions of its own beside filaments whose types react with nothing).
    if (ranges_[k].begin != range.begin || ranges_[k].end != range.end || ranges_[k].owner != range.owner) continue;
    if (claimed_[k]) throw std::logic_error("rate factors of \"" + ranges_[k].owner + "\" are claimed already");
    claimed_[k] = 1;
    return RateFactors(this, ranges_[k]);
  }
  throw std::logic_error("rate factors of \"" + range.owner + "\": not a reaction range of the model");
}

void EngineBase::setReactionHook(const ReactionRange& range, ReactionHook* hook) {
  if (range.begin < 0 || range.end > R_ || range.end < range.begin)
    throw std::out_of_range("chemistry engine: reaction range of \"" + range.owner + "\" outside the model");
  for (Index r = range.begin; r < range.end; ++r) hooks_[r] = hook;
}

ChemistryState EngineBase::state() const {
  ChemistryState s;
  s.species = S_;
  s.copies.assign(copies_.begin(), copies_.begin() + static_cast<std::ptrdiff_t>(region_start_[1]) * S_);
  s.random_counter = rng_.counter();
  s.random_used = rng_.usedInBlock();
  s.time = time_;
  s.events = events_;
  s.diffusion_events = diffusion_events_;
  s.reaction_events = reaction_events_;
  return s;
}

void EngineBase::restore(const ChemistryState& s) {
  if (s.reaction_events.size() != reaction_events_.size())
    throw std::invalid_argument("chemistry engine: checkpoint has " + std::to_string(s.reaction_events.size()) +
                                " reaction counters, the model " + std::to_string(reaction_events_.size()));
  const Index n0 = region_start_[1];
  if (s.copies.size() != static_cast<std::size_t>(n0) * S_)
    throw std::invalid_argument("chemistry engine: checkpoint has " + std::to_string(s.copies.size()) +
                                " copies for " + std::to_string(n0) + " subvolumes x " + std::to_string(S_) +
                                " species");
  for (Index i = 0; i < n0; ++i)
    for (Index sp = 0; sp < S_; ++sp) {
      const int n = s.copies[static_cast<std::size_t>(i) * S_ + sp];
      if (n < 0 || (n > 0 && !active(i, sp)))
        throw std::invalid_argument("chemistry engine: checkpoint copies of species " + std::to_string(sp) +
                                    " where it cannot be");
      copies_[static_cast<std::size_t>(i) * S_ + sp] = n;
    }
  for (Index i = 0; i < N_; ++i) refreshSubvolume(i);
  rng_.restore(s.random_counter, s.random_used);
  time_ = s.time;
  events_ = s.events;
  reaction_events_ = s.reaction_events;
  diffusion_events_ = s.diffusion_events;
}

void EngineBase::setSurface(Index surface, const SubvolumeGraph& graph, const std::vector<Index>& holders,
                            const std::vector<int>& copies) {
  const Index region = surface + 1;
  if (surface < 0 || region >= static_cast<Index>(graphs_.size()))
    throw std::out_of_range("chemistry engine: no surface " + std::to_string(surface));
  validate(graph, "chemistry: the subvolumes of surface " + std::to_string(surface));
  if (holders.size() != static_cast<std::size_t>(graph.count()) ||
      copies.size() != static_cast<std::size_t>(graph.count()) * S_)
    throw std::invalid_argument("chemistry engine: setSurface needs one holder and " + std::to_string(S_) +
                                " copies per subvolume");
  for (Index h : holders)
    if (h < 0 || h >= graphs_[0].count()) throw std::invalid_argument("chemistry engine: holder outside the 3D subvolumes");
  for (std::size_t i = 0; i < copies.size(); ++i)
    if (copies[i] < 0 || (copies[i] > 0 && net_.speciesRegion[i % S_] != region))
      throw std::invalid_argument("chemistry engine: bad copies of species " + std::to_string(i % S_) +
                                  " on surface " + std::to_string(surface));
  graphs_[region] = graph;
  holders_[region] = holders;
  for (Index s = 0; s < S_; ++s)
    if (net_.speciesRegion[s] == region) {
      drift_[s].clear();
      interaction_[s] = SurfaceInteraction{};
      field_[s].clear();
      interacts_[s] = 0;
      paired_[s] = 0;
      couplings_[s].clear();
      for (std::vector<Index>* list : {&unbinding_, &binding_})
        for (Index& u : *list)
          if (u == s) u = -1;
    }
  layOut(region, copies);
  relaidOut();
}

bool EngineBase::capAccepts(Index r, Index i) const {
  if (room_.empty()) return true;
  double added = 0.0;
  for (const SpeciesChange& change : net_.changes[r])
    if (!change.held) added += change.delta * species_[change.species].footprint;
  return !(added > 0.0) || covered(i) + added <= room_[i];
}

void EngineBase::setSurfaceDrift(Index species, const std::vector<double>& factors) {
  if (species < 0 || species >= S_) throw std::out_of_range("chemistry engine: no species " + std::to_string(species));
  const Index region = net_.speciesRegion[species];
  if (region == 0) throw std::invalid_argument("chemistry engine: only surface species drift");
  if (interacting(species))
    throw std::invalid_argument("chemistry engine: an interacting species drifts through its interaction's potential");
  if (factors.size() != static_cast<std::size_t>(graphs_[region].numEdges()))
    throw std::invalid_argument("chemistry engine: setSurfaceDrift needs one factor per edge of the surface");
  for (double f : factors)
    if (!(f >= 0.0 && std::isfinite(f)))
      throw std::invalid_argument("chemistry engine: a drift factor negative or not finite");
  drift_[species] = factors;
  computeHopRates();
  for (Index i = region_start_[region]; i < region_start_[region + 1]; ++i) refreshSubvolume(i);
}

void EngineBase::setConfinement(Index species, const std::vector<double>& volume, const std::vector<double>& edges) {
  if (species < 0 || species >= S_) throw std::out_of_range("chemistry engine: no species " + std::to_string(species));
  if (net_.speciesRegion[species] != 0)
    throw std::invalid_argument("chemistry engine: only 3D species can be confined");
  const Index n0 = region_start_[1];
  const Index e0 = edge_start_[n0];
  if (volume.size() != static_cast<std::size_t>(n0) || edges.size() != static_cast<std::size_t>(e0))
    throw std::invalid_argument(
        "chemistry engine: confinement needs one volume fraction per 3D subvolume and one area fraction per 3D edge");
  for (Index i = 0; i < n0; ++i) {
    bool ok = volume[i] >= 0.0 && volume[i] <= 1.0;
    for (Index e = edge_start_[i]; e < edge_start_[i + 1]; ++e) ok = ok && edges[e] >= 0.0 && edges[e] <= 1.0;
    if (!ok)
      throw std::invalid_argument("chemistry engine: confinement fractions outside [0, 1] in subvolume " +
                                  std::to_string(i));
  }
  // Refused before anything changes, so a failed call leaves the engine as it was.
  bool any_active = false, any_copies = false;
  for (Index i = 0; i < n0; ++i) {
    any_active = any_active || volume[i] > 0.0;
    any_copies = any_copies || copies_[static_cast<std::size_t>(i) * S_ + species] > 0;
  }
  if (any_copies && !any_active)
    throw std::runtime_error("chemistry engine: species " + std::to_string(species) +
                             " has copies but no subvolume with volume on its side of the membrane");
  if (volume_.empty()) {
    volume_.assign(static_cast<std::size_t>(n0) * S_, 1.0);
    edge_fraction_.assign(static_cast<std::size_t>(e0) * S_, 1.0);
  }
  // The subvolumes whose rates change: their own fraction or an edge's changed (hop rates
  // out of a subvolume read its neighbours' fractions too, hence both ends).
  std::vector<char> dirty(N_, 0);
  if (!confined_[species]) {
    confined_[species] = 1;
    std::fill(dirty.begin(), dirty.end(), 1);
    for (Index r = 0; r < R_; ++r)
      if (net_.sideSpecies[r] == species && net_.region[r] == 0) scale_species_[r] = species;
  }
  for (Index i = 0; i < n0; ++i) {
    double& f = volume_[static_cast<std::size_t>(i) * S_ + species];
    if (f != volume[i]) {
      dirty[i] = 1;
      for (Index e = edge_start_[i]; e < edge_start_[i + 1]; ++e) dirty[edge_target_[e]] = 1;
      for (Index h : held_[i]) dirty[h] = 1;
    }
    f = volume[i];
    for (Index e = edge_start_[i]; e < edge_start_[i + 1]; ++e) {
      double& a = edge_fraction_[static_cast<std::size_t>(e) * S_ + species];
      if (a != edges[e]) dirty[i] = 1;
      a = edges[e];
    }
  }
  computeHopRates();
  relocate(species, dirty);
  for (Index i = 0; i < N_; ++i)
    if (dirty[i]) refreshSubvolume(i);
}

// Multi-source breadth-first search from every active subvolume (in index order, edges
// in order): each subvolume learns its nearest active one, deterministically.
void EngineBase::relocate(Index s, std::vector<char>& dirty) {
  const Index n0 = region_start_[1];
  bool stranded = false;
  for (Index i = 0; i < n0 && !stranded; ++i)
    stranded = !active(i, s) && copies_[static_cast<std::size_t>(i) * S_ + s] > 0;
  if (!stranded) return;
  std::vector<Index> nearest(n0, -1);
  std::deque<Index> queue;
  for (Index i = 0; i < n0; ++i)
    if (active(i, s)) {
      nearest[i] = i;
      queue.push_back(i);
    }
  while (!queue.empty()) {
    const Index i = queue.front();
    queue.pop_front();
    for (Index e = edge_start_[i]; e < edge_start_[i + 1]; ++e) {
      const Index j = edge_target_[e];
      if (nearest[j] >= 0) continue;
      nearest[j] = nearest[i];
      queue.push_back(j);
    }
  }
  for (Index i = 0; i < n0; ++i) {
    int& n = copies_[static_cast<std::size_t>(i) * S_ + s];
    if (active(i, s) || n == 0) continue;
    copies_[static_cast<std::size_t>(nearest[i]) * S_ + s] += n;
    n = 0;
    dirty[i] = dirty[nearest[i]] = 1;
    for (Index h : held_[i]) dirty[h] = 1;
    for (Index h : held_[nearest[i]]) dirty[h] = 1;
  }
}

}  // namespace cortex
