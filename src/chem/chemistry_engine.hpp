// The exact stochastic engine: reactions in every subvolume and diffusion hops along the
// edges of the subvolume graphs, fired one event at a time.
//
// Two implementations share this interface and one test body: the next-subvolume method
// (Elf & Ehrenberg 2004: per-subvolume propensity sums in an indexed priority queue, so
// the cost per event grows only with log(subvolumes)) for real runs, and Gillespie's
// direct method over all channels, simple enough to trust, for tests to compare against.
//
// Subvolumes are numbered region by region: the 3D ones (ChemistryModel::volumes) first,
// then each surface's (given by setSurface) in the order of ChemistryModel::surfaces.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "chem/chemistry_model.hpp"
#include "chem/hop_drift.hpp"
#include "chem/reaction_hook.hpp"
#include "core/random.hpp"

namespace cortex {

enum class EngineKind { kNextSubvolume, kDirect };

// An engine's whole state between advances (see ChemistryEngine): what a checkpoint
// stores. Surface copies are not in it: they belong to their membranes.
struct ChemistryState {
  Index species = 0;        // copies per subvolume
  std::vector<int> copies;  // over the 3D subvolumes, [i * species + s]
  std::uint64_t random_counter = 0;
  int random_used = 4;
  double time = 0.0;
  std::int64_t events = 0, diffusion_events = 0;
  std::vector<std::int64_t> reaction_events;

  // f(name, field) for every scalar field (checkpoints).
  template <class Self, class F>
  static void fields(Self& s, F&& f) {
    f("random_counter", s.random_counter);
    f("random_used", s.random_used);
    f("time", s.time);
    f("events", s.events);
    f("diffusion_events", s.diffusion_events);
  }
};

class ChemistryEngine;

// The one writer of a reaction range's rate factors (ChemistryEngine::claimRateFactors).
// A rate factor scales reaction r's propensity in one subvolume (mechanochemical
// feedback, reactions restricted to a region); it is 1 until set.
class RateFactors {
 public:
  RateFactors() = default;
  // `reaction` is a model index inside range(); throws std::out_of_range otherwise, and
  // std::invalid_argument for a factor that is negative or not finite.
  void set(Index reaction, Index subvolume, double factor) const;
  const ReactionRange& range() const { return range_; }

 private:
  friend class EngineBase;
  RateFactors(ChemistryEngine* engine, ReactionRange range) : engine_(engine), range_(std::move(range)) {}
  ChemistryEngine* engine_ = nullptr;
  ReactionRange range_;
};

// Between advances an engine keeps no pending event times (waiting times are
// exponential, hence memoryless, so they are drawn afresh at the start of every
// advance): its whole state is the copies, the rate factors, the time and the random
// stream. That is what a checkpoint stores, and why every setter between advances is
// exact.
class ChemistryEngine {
 public:
  virtual ~ChemistryEngine() = default;

  // Fires every event up to t_end (s); afterwards time() == t_end.
  virtual void advance(double t_end) = 0;
  virtual double time() const = 0;

  virtual Index numSubvolumes() const = 0;
  // Subvolumes of region k (0: 3D, k >= 1: surface k - 1) are [regionStart(k), regionStart(k + 1)).
  virtual Index regionStart(Index region) const = 0;

  // Copies of `species` in `subvolume`. Setting them between advances updates only the
  // propensities that depend on them.
  virtual int copies(Index subvolume, Index species) const = 0;
  virtual void setCopies(Index subvolume, Index species, int n) = 0;

  // The rate factors of `range` (one of the model's ranges), to its owner alone: throws
  // std::logic_error if the range is unknown or claimed already.
  virtual RateFactors claimRateFactors(const ReactionRange& range) = 0;

  // Who carries out the reactions of `range` (not owned; must outlive the engine's
  // advances). Reactions without a hook fire as plain mass action.
  virtual void setReactionHook(const ReactionRange& range, ReactionHook* hook) = 0;

  // Confines the 3D `species` to one side of a membrane (thesis 2.2.4.2). Per 3D
  // subvolume, `volume` is the fraction of its volume on that side, and per directed edge
  // of the 3D graph `edges` the fraction of the contact area on that side; an edge and
  // its reverse must get the same value (CompartmentSlices does this). Then the per-copy
  // hop rate along an edge is D/l^2 * a / f_source (size * rate stays symmetric, so the
  // stationary distribution is uniform in the confined volume); subvolumes with f = 0 are
  // inactive: no hops in or out. Propensities of 3D reactions whose species are confined
  // (their first reactant, or first product for order 0, decides) scale by f (order 0),
  // 1 (order 1) or 1/f (order 2), per-site reactions (ReactionDef::per_site) by f^-order,
  // surface reactions by 1/f per 3D reactant in their holder, and all are 0 where f = 0.
  // Copies sitting in a subvolume that becomes inactive move to the nearest active one
  // (breadth first along edges, ties by subvolume index and edge order), so none is lost;
  // throws std::runtime_error if they have nowhere to go, std::invalid_argument for
  // fractions outside [0, 1] or of the wrong size. Only subvolumes whose rates changed
  // are recomputed. Unconfined species (the default) behave as f = a = 1.
  virtual void setConfinement(Index species, const std::vector<double>& volume, const std::vector<double>& edges) = 0;

  // Replaces the subvolumes of `surface` (a remeshed membrane): `graph` its dual cells,
  // `holders` the 3D subvolume holding each, `copies` the copies in each (subvolume-major,
  // [i * species + s]; non-zero only for that surface's species), carried over by the
  // caller so that none is lost. Rate factors of its reactions there restart at 1.
  // Throws InputError for an inconsistent graph, std::invalid_argument for bad sizes.
  virtual void setSurface(Index surface, const SubvolumeGraph& graph, const std::vector<Index>& holders,
                          const std::vector<int>& copies) = 0;

  // Multiplies the per-copy hop rates of surface species `species` along the directed
  // edges of its surface's current graph (the one setSurface gave, in its edge order) by
  // `factors`: the drift of a potential (docs/proteins.md). The caller keeps detailed
  // balance (factor_ij / factor_ji = e^{-β(h_j - h_i)} for stationary copies ∝ size ·
  // e^{-βh}). setSurface resets the factors to 1. Throws std::invalid_argument for a 3D
  // species, a factor negative or not finite, or a count other than the graph's edges.
  virtual void setSurfaceDrift(Index species, const std::vector<double>& factors) = 0;

  // A surface species whose copies attract or repel each other (thesis eqs. 3.4–3.5):
  // a copy in subvolume j feels h_j = V_j + R_j, R = K N the field of the other copies
  // (N per subvolume, K symmetric with the graph's sparsity). A hop i → k then changes the
  // energy W = Σ V_j N_j + ½ Nᵀ K N − ½ Σ K_jj N_j (pairs, no self-pairs) by
  //   x = V_k − V_i + R_k − R_i − K_ik + K_ii      (k_BT),
  // and its rate is the free one times the drift factor of `scheme` (chem/hop_drift.hpp);
  // the exponential one keeps detailed balance with e^{−W} exactly. Rates are kept exact
  // event by event: after each hop the field and the hop rates around both ends are
  // recomputed.
  //
  // An on-site energy F_j(N_j) of the copies sharing a subvolume may come on top (crowded
  // curvature sensing, sim/curvature_sensing.hpp): given as arrival energies
  // a_j(m) = F_j(m + 1) − F_j(m), it adds a_k(N_k) − a_i(N_i − 1) to x, and W gains
  // Σ_j F_j(N_j); rates around both ends of a hop are recomputed as for the field.
  //
  // Unbinding (a reaction taking one copy of the species into 3D species only) from j
  // fires at r e^{V_j + R_j − K_jj + a_j(N_j − 1)}, the energy its copy leaves, so binding
  // (aggregated, ReactionNetwork::aggregated) keeps detailed balance with e^{−W} (thesis
  // eq. 3.14). Other reactions of the species fire at their mass-action propensity, as
  // the thesis' surface reactions do (eq. 3.13); desorption of several copies at once is
  // refused.
  struct SurfaceInteraction {
    std::vector<double> potential;  // per subvolume of the surface: V_j
    std::vector<double> self;       // per subvolume: K_jj
    std::vector<double> pair;       // per directed edge of the surface's graph: K_jk = K_kj
    // Arrival energies, row j = [onsite_start[j], onsite_start[j + 1]) of `onsite`, a_j(m)
    // at m = 0, 1, ...; past the row's end its last value; an empty row is 0. Both empty:
    // no on-site energy.
    std::vector<Index> onsite_start;  // per subvolume + 1
    std::vector<double> onsite;
    DriftScheme scheme = DriftScheme::kExponential;
  };
  // Gives surface species `species` its interaction on the surface's current graph
  // (setSurface clears it, as it does drift factors). Throws std::invalid_argument for a
  // 3D species, one that a reaction desorbs several copies at a time, sizes other than
  // the graph's, values not finite, or K not symmetric.
  virtual void setSurfaceInteraction(Index species, SurfaceInteraction interaction) = 0;
  // Couples two interacting species of one surface (setSurfaceInteraction done for both)
  // by a symmetric kernel K^ab (`self` per subvolume, `pair` per directed edge, as an
  // interaction's): each copy of a feels R_a += K^ab N_b and each of b R_b += K^ab N_a,
  // and W gains N_aᵀ K^ab N_b (no self-term: the copies are distinct). Hops and unbinding
  // of both stay exact as above. Throws std::invalid_argument for a == b, species not
  // interacting on one surface, a pair already coupled, sizes, values or symmetry.
  virtual void setSurfaceCoupling(Index a, Index b, std::vector<double> self, std::vector<double> pair) = 0;

  // The total propensity (events/s) at the current copies and rates, and the channel
  // contributing most (for messages: "diffusion of \"A\"", "reaction \"A -> B\"") with
  // what sets its rate.
  struct Load {
    double total = 0.0;
    double largest = 0.0;
    std::string largest_channel;
    std::string largest_cause;
  };
  virtual Load load() const = 0;
  // An advance that would fire more than `max` events (expected from the propensities at
  // its start, or counted while it runs) stops with a RunError instead of running for
  // hours: rates or diffusion constants far too large for the window. Default 1e9.
  virtual void setEventLimit(double max) = 0;
  // Called within an advance every 2^20 events (with the events limit's check): it may
  // throw to abandon the advance (a stop request, RunStopped), leaving the engine unusable.
  virtual void setInterrupt(std::function<void()> poll) = 0;
  // The same refusal now, for an advance of `window` s from the current state, with every
  // factor a membrane species' energies put on its hops and unbinding: what `cortex check`
  // tells before a run starts. Throws RunError with the advance's message.
  virtual void checkLoad(double window) const = 0;

  virtual std::int64_t events() const = 0;
  // Events fired per reaction (index as in the model); diffusion hops counted apart.
  virtual const std::vector<std::int64_t>& reactionEvents() const = 0;
  virtual std::int64_t diffusionEvents() const = 0;

  // The random stream and clock, for checkpoints.
  virtual const RandomStream& random() const = 0;
  virtual ChemistryState state() const = 0;
  // Continues from a state: its copies (throws std::invalid_argument unless there is one
  // per 3D subvolume and species), clock, stream and counters.
  virtual void restore(const ChemistryState& state) = 0;

 private:
  friend class RateFactors;
  virtual void setRateFactor(Index reaction, Index subvolume, double factor) = 0;
};

// `copies` is subvolume-major over the 3D subvolumes: copies[i * species + s].
std::unique_ptr<ChemistryEngine> makeChemistryEngine(EngineKind kind, const ChemistryModel& model,
                                                     const std::vector<int>& copies, std::uint64_t seed);

}  // namespace cortex
