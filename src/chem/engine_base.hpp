// What both engine implementations share: the compiled network, the subvolumes of every
// region laid out as one graph, the copies, hop rates and confinement, and the clock,
// stream and counters that make up a checkpoint.
#pragma once

#include <limits>

#include "chem/chemistry_engine.hpp"
#include "chem/reaction_network.hpp"

namespace cortex {

class EngineBase : public ChemistryEngine {
 public:
  double time() const override { return time_; }
  Index numSubvolumes() const override { return N_; }
  Index regionStart(Index region) const override { return region_start_.at(region); }
  int copies(Index subvolume, Index species) const override { return copies_[slot(subvolume, species)]; }
  std::int64_t events() const override { return events_; }
  const std::vector<std::int64_t>& reactionEvents() const override { return reaction_events_; }
  std::int64_t diffusionEvents() const override { return diffusion_events_; }
  const RandomStream& random() const override { return rng_; }
  RateFactors claimRateFactors(const ReactionRange& range) override;
  void setReactionHook(const ReactionRange& range, ReactionHook* hook) override;
  ChemistryState state() const override;
  Load load() const override;
  void setEventLimit(double max) override { event_limit_ = max; }
  void setInterrupt(std::function<void()> poll) override { interrupt_ = std::move(poll); }
  void checkLoad(double window) const override { checkLoad(totalRate(), window); }
  void restore(const ChemistryState& state) override;
  // Stores the confinement, relocates stranded copies, then lets the engine recompute
  // the subvolumes whose rates changed (refreshSubvolume).
  void setConfinement(Index species, const std::vector<double>& volume, const std::vector<double>& edges) override;
  void setSurface(Index surface, const SubvolumeGraph& graph, const std::vector<Index>& holders,
                  const std::vector<int>& copies) override;
  void setSurfaceDrift(Index species, const std::vector<double>& factors) override;
  void setSurfaceInteraction(Index species, SurfaceInteraction interaction) override;
  void setSurfaceCoupling(Index a, Index b, std::vector<double> self, std::vector<double> pair) override;

 protected:
  // Throws InputError for an invalid model or negative copies, std::invalid_argument
  // when `copies` does not have (3D subvolumes) * species entries.
  EngineBase(const ChemistryModel& model, const std::vector<int>& copies, std::uint64_t seed);

  // Index of (subvolume, species) in copies_; throws std::out_of_range.
  std::size_t slot(Index subvolume, Index species) const;
  // Checks the arguments of setCopies / setRateFactor; throws std::out_of_range or
  // std::invalid_argument.
  void checkCopies(Index subvolume, Index species, int n) const;
  void checkRateFactor(Index reaction, Index subvolume, double factor) const;
  // Copy numbers are 32-bit: a reaction that would push one past 2^31 - 1 stops the run
  // (RunError) instead of wrapping around.
  // Reaction `reaction` adding `delta` copies of `species` to the n in `subvolume`.
  void checkGrowth(int n, int delta, Index subvolume, Index species, Index reaction) const {
    if (delta > 0 && n > std::numeric_limits<int>::max() - delta) growthOverflow(subvolume, species, reaction);
  }
  [[noreturn]] void growthOverflow(Index subvolume, Index species, Index reaction) const;
  // Refuses the rest of an advance, `dt` at total propensity `total` (events/s) after
  // `drawn` events of it (void ones included: they cost the same), when the whole is
  // expected to exceed the event limit (RunError naming the largest channel). Checked at
  // the start and every 2^20 events: a network that explodes within a window (an
  // autocatalytic reaction) stops within seconds instead of running for hours, or for ever
  // when a crowding cap turns its events void. Within an advance (drawn > 0) it first
  // calls the interrupt (setInterrupt).
  void checkLoad(double total, double dt, std::int64_t drawn = 0) const;
  static constexpr std::int64_t kLoadCheckInterval = std::int64_t{1} << 20;
  double event_limit_ = 1e9;
  std::function<void()> interrupt_;

  // The total propensity (events/s) as the engine keeps it, energies' factors included.
  virtual double totalRate() const = 0;
  // Recomputes every propensity of subvolume i from copies_, the factors and the rates.
  virtual void refreshSubvolume(Index i) = 0;
  // The subvolumes were laid out anew (setSurface): resize and recompute everything.
  virtual void relaidOut() = 0;

  // Aggregated reactions (ReactionNetwork::aggregated), carried by the 3D subvolume h
  // holding the surface subvolumes j where they fire: weight c_j (rate factor, constant,
  // confinement scale); the weights of the subvolumes h holds and their sum, cached per
  // (h, r) by refreshBindingWeight(s), which whatever changes a weight calls (a rate
  // factor, a confinement, every subvolume at the start of an advance); h's propensity;
  // and the subvolume where one fires, drawn ∝ c_j from the cache (−1 if every weight is 0).
  bool aggregated(Index r) const { return net_.aggregated[r] != 0; }
  double bindingWeight(Index j, Index r) const {
    return factor_[static_cast<std::size_t>(j) * R_ + r] * constantAt(j, r) * confinementScale(j, r);
  }
  void refreshBindingWeight(Index h, Index r);
  void refreshBindingWeights(Index h);
  double bindingPropensity(Index h, Index r) const {
    const int* n = &copies_[static_cast<std::size_t>(h) * S_];
    return binding_weight_[static_cast<std::size_t>(h) * R_ + r] * combinations(net_.kernels[r], n, n);
  }
  Index drawBindingSite(Index h, Index r);
  // Propensity of reaction r in subvolume i from rate_[i * R + r] (the engines' cached
  // factor × constant): aggregated reactions on their 3D holder, 0 on surface subvolumes.
  double propensityAt(Index i, Index r, double rate) const {
    if (aggregated(r)) return region_of_[i] == 0 ? bindingPropensity(i, r) : 0.0;
    const double p = rate * confinementScale(i, r) *
                     combinations(net_.kernels[r], &copies_[static_cast<std::size_t>(i) * S_],
                                  &copies_[static_cast<std::size_t>(holder_[i]) * S_]);
    // No factor where r cannot fire (another region: the species' potential has no entry).
    if (p == 0.0 || unbinding_.empty() || unbinding_[r] < 0 || region_of_[i] == 0) return p;
    return p * unbindingFactor(i, unbinding_[r]);
  }

  // Whether copies of s interact (setSurfaceInteraction).
  bool interacting(Index s) const { return interacts_[s] != 0; }
  // The energy (k_BT) of a copy of interacting species s leaving surface subvolume i,
  // V_i + R_i − K_ii + a_i(N_i − 1), with `added` more copies there than now (0: a copy
  // unbinding now; 1: the copy a binding would bring).
  double leavingEnergy(Index i, Index s, int added) const;
  // e^{βV} of the copy unbinding from i, V = leavingEnergy(i, s, 0) capped at
  // kLargestUnbindingEnergy; the rest of V goes to binding (energyAccepts).
  double unbindingFactor(Index i, Index s) const;
  // Binding reaction r into surface subvolume i, where the copy would have a leaving
  // energy V over kLargestUnbindingEnergy: accepted with probability
  // e^{−(βV − kLargestUnbindingEnergy)}, exact thinning (a void event otherwise). Draws a
  // random number only then, so runs that never meet such a state draw the same numbers.
  bool energyAccepts(Index r, Index i);
  // Whether reaction r, drawn in subvolume i, is carried out: the crowding cap, then the
  // energy's share of binding, then r's hook (each may void it; this order fixes which
  // random numbers are drawn, in both engines).
  bool accepts(Index r, Index i) { return capAccepts(r, i) && energyAccepts(r, i) && hookAccepts(r, i); }
  // k_BT. Eq. 3.14 puts a copy's whole energy on its unbinding, r e^{βV}, and binds at the
  // plain rate: a copy binding into a cell it can hardly share (a second protein larger
  // than the cell: ~800 k_BT of curvature energy) would leave at r e^{800}, an infinite
  // rate that stopped the run. Above this energy the excess weighs binding instead:
  // unbinding at most 10⁶ r, binding into the state thinned by e^{−excess}. The ratio of
  // the two, hence detailed balance and every equilibrium, is eq. 3.14's; only how fast
  // such states are entered and left differs (docs/proteins.md).
  static constexpr double kLargestUnbindingEnergy = 13.815510557964274;  // ln 10⁶
  // Whether the field of interacting species u reads the copies of s (u is s or coupled
  // to it, setSurfaceCoupling).
  bool fieldReads(Index u, Index s) const {
    if (u == s) return true;
    for (const Coupling& c : couplings_[s])
      if (c.other == u) return true;
    return false;
  }
  // How many of interactionChanged's subvolumes come first as those whose field changed.
  std::size_t interactionFieldsChanged() const { return near_.size(); }
  // Per reaction: the interacting species it unbinds, −1 for none; empty if none does.
  std::vector<Index> unbinding_;
  // Per reaction: the interacting species it binds (one copy from 3D species), −1 for
  // none; empty if none does.
  std::vector<Index> binding_;
  // After copies of interacting species s changed in subvolumes a and b (a hop a → b, or
  // a == b): recomputes the field R around them and the hop rates that read it (each a
  // pure function of the copies, so a restored engine gets the same numbers). Returns the
  // subvolumes whose hopOut changed, for the engine to resum.
  const std::vector<Index>& interactionChanged(Index s, Index a, Index b);

  // Lets reaction r's hook carry it out in subvolume i; false: the event is void.
  bool hookAccepts(Index r, Index i) { return !hooks_[r] || hooks_[r]->fired(r, i, *this, rng_); }
  // The crowding cap (SpeciesDef::footprint): whether `delta` more copies of s would
  // overfill subvolume i, and whether reaction r may fire in i without overfilling it (by
  // its net change of covered area). A hop or reaction refused here is a void event: its
  // propensity is an upper bound of the true one and this the exact thinning.
  bool crowded(Index i, Index s, int delta) const {
    if (room_.empty() || !(species_[s].footprint > 0.0)) return false;
    return covered(i) + delta * species_[s].footprint > room_[i];
  }
  bool capAccepts(Index r, Index i) const;
  // Σ_s n_s a_s over the species with a footprint in subvolume i, nm².
  double covered(Index i) const {
    double area = 0.0;
    for (Index s : crowding_[region_of_[i]]) area += copies_[static_cast<std::size_t>(i) * S_ + s] * species_[s].footprint;
    return area;
  }

  // Propensity constant of reaction r in subvolume i (0 outside r's region), before its
  // rate factor and confinement scale.
  double constantAt(Index i, Index r) const {
    if (net_.region[r] != region_of_[i]) return 0.0;
    return net_.constant(r, size_[i], size_[holder_[i]]);
  }
  // Factor by which confinement scales reaction r's propensity in subvolume i.
  double confinementScale(Index i, Index r) const {
    if (region_of_[i] != 0) return heldScale(i, r);
    const Index s = scale_species_[r];
    if (s < 0) return 1.0;
    const double f = volume_[static_cast<std::size_t>(i) * S_ + s];
    if (!(f > 0.0)) return 0.0;
    const int order = net_.order[r];
    // A per-site propensity (an end, a pair of sites) is k prod [X], each concentration
    // n / (f V), whatever the order.
    if (net_.perSite[r]) return order == 0 ? 1.0 : order == 1 ? 1.0 / f : 1.0 / (f * f);
    return order == 0 ? f : order == 2 ? 1.0 / f : 1.0;
  }
  // A 3D copy of `species` may be in subvolume i (not an inactive, confined-out one).
  bool active(Index i, Index s) const {
    if (region_of_[i] != net_.speciesRegion[s]) return false;
    return region_of_[i] != 0 || volume_.empty() || volume_[static_cast<std::size_t>(i) * S_ + s] > 0.0;
  }

  // Per-copy hop rates. A species is weighted when its rates differ from edge to edge
  // (confined, or on a graph with unequal hop lengths): then hopOut / edgeRate hold them;
  // otherwise every edge has hopRate(s).
  bool weighted(Index s) const { return weighted_[s] != 0; }
  double hopRate(Index s) const { return hop_rate_[s]; }
  double hopOut(Index i, Index s) const { return hop_out_[static_cast<std::size_t>(i) * S_ + s]; }
  double edgeRate(Index e, Index s) const { return edge_rate_[static_cast<std::size_t>(e) * S_ + s]; }
  // Total per-copy hop rate of species s out of subvolume i.
  double hopOutOf(Index i, Index s) const { return weighted(s) ? hopOut(i, s) : degree(i) * hop_rate_[s]; }
  Index degree(Index i) const { return edge_start_[i + 1] - edge_start_[i]; }
  // The 3D subvolumes' lattice shape (SubvolumeGraph::lattice), zeros if none.
  const std::array<int, 3>& lattice() const { return graphs_[0].lattice; }

  ReactionNetwork net_;
  std::vector<SpeciesDef> species_;
  std::vector<std::string> equations_;  // per reaction, for messages
  Index S_, R_, N_ = 0;        // species, reactions, subvolumes (all regions)
  // The subvolumes of all regions as one graph (edges never cross regions).
  std::vector<Index> region_start_;  // per region, and one past the end
  std::vector<Index> region_of_;     // per subvolume
  std::vector<double> size_;         // per subvolume: nm^3 or nm^2
  std::vector<Index> holder_;        // per subvolume: the 3D subvolume holding it (itself if 3D)
  Rows<Index> held_;                 // per subvolume: the surface subvolumes it holds (3D ones only)
  std::vector<Index> edge_start_, edge_target_;
  std::vector<double> hop_length2_;
  std::vector<std::vector<Index>> diffusing_;  // per region: its species with D > 0, ascending
  std::vector<int> copies_;          // subvolume-major: copies_[i * S_ + s]
  std::vector<double> factor_;       // rate factors, [i * R_ + r]
  RandomStream rng_;
  double time_ = 0.0;
  std::int64_t events_ = 0;
  std::vector<std::int64_t> reaction_events_;
  std::int64_t diffusion_events_ = 0;

 private:
  double heldScale(Index i, Index r) const;
  // Lays out the regions' graphs as one; keeps copies and factors of regions other than
  // `replaced` (whose new copies are `fresh`), and recomputes every hop rate.
  void layOut(Index replaced, const std::vector<int>& fresh);
  void computeHopRates();
  // Interactions (surface_interaction.cpp): R_i of species s from the copies; the
  // per-copy rate along edge e out of subvolume i; edge_rate_ and hop_out_ of i.
  double pairField(Index s, Index i) const;
  // a_j(m) of species s at region-local subvolume a (SurfaceInteraction::onsite).
  double arrivalEnergy(Index s, Index a, int m) const;
  // What the rates of interacting species s read, looked up once for the many edges a
  // hop changes: its terms (indexed from its region's first subvolume and edge).
  struct InteractionView {
    const double *potential, *self, *pair, *field;
    bool onsite;  // on-site energies (arrivalEnergy)
    double diffusion;
    Index species, first, first_edge;
    bool exponential;
  };
  InteractionView interactionView(Index s) const;
  double interactionRate(const InteractionView& w, Index i, Index e) const;
  void computeInteractionRates(const InteractionView& w, Index i);
  void computeInteractionRates(Index s, Index i) { computeInteractionRates(interactionView(s), i); }
  // Moves copies of s out of inactive subvolumes; marks the subvolumes touched.
  void relocate(Index s, std::vector<char>& dirty);

  std::vector<SubvolumeGraph> graphs_;        // per region
  std::vector<std::vector<Index>> holders_;   // per surface region
  std::vector<ReactionHook*> hooks_;          // per reaction
  std::vector<ReactionRange> ranges_;
  std::vector<char> claimed_;                 // per range
  std::vector<char> weighted_;                // per species
  std::vector<double> hop_rate_;              // per species: D / l^2 when not weighted
  std::vector<double> hop_out_, edge_rate_;   // [i * S + s], [e * S + s]; weighted species only
  std::vector<char> confined_;                // per species
  std::vector<Index> scale_species_;          // per reaction: its side species once confined, else -1
  // Confinement inputs per species ([i * S + s] over the 3D subvolumes; 1 when unconfined)
  // and per 3D edge ([e * S + s]), allocated at the first setConfinement.
  std::vector<double> volume_, edge_fraction_;
  // Per species: hop-rate factors along its surface's edges (region-local edge order),
  // empty for none (setSurfaceDrift).
  std::vector<std::vector<double>> drift_;
  std::vector<Index> aggregated_;       // the aggregated reactions
  std::vector<double> binding_weight_;  // [h * R + r] over the 3D subvolumes, for aggregated r
  // Per aggregated reaction (its slot in aggregated_), c_j of every surface subvolume in
  // held_'s order (held_.values): what the sums in binding_weight_ add up.
  std::vector<std::vector<double>> site_weight_;
  std::vector<Index> aggregated_slot_;  // per reaction: its index in aggregated_, or −1
  // Per species: its interaction (potential, self and pair per region-local subvolume and
  // edge; empty for none) and field R per region-local subvolume.
  std::vector<SurfaceInteraction> interaction_;
  std::vector<std::vector<double>> field_;
  std::vector<char> interacts_;  // per species: has an interaction (one byte for the hop path)
  std::vector<char> paired_;     // per species: its interaction has pair terms (K ≠ 0) or couplings
  // Per species: the other species its field reads (setSurfaceCoupling), with the kernel.
  struct Coupling {
    Index other;
    std::vector<double> self, pair;  // region-local
  };
  std::vector<std::vector<Coupling>> couplings_;
  // Scratch of interactionChanged: visit marks per subvolume, and the sets it builds.
  std::vector<std::uint32_t> mark_;
  std::uint32_t mark_round_ = 0;
  std::vector<Index> near_, reach_;
  // The crowding cap: per subvolume crowdingRoom(|C_i|), and per region the species with a
  // footprint; both empty when no species has one.
  std::vector<double> room_;
  std::vector<std::vector<Index>> crowding_;
};

}  // namespace cortex
