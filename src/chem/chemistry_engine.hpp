// The exact stochastic engine: reactions in every compartment and diffusion hops between
// face neighbours (rate D/h^2 per copy and face), fired one event at a time.
//
// Two implementations share this interface and one test body: the next-subvolume method
// (Elf & Ehrenberg 2004: per-compartment propensity sums in an indexed priority queue,
// so the cost per event grows only with log(compartments)) for real runs, and Gillespie's
// direct method over all channels, simple enough to trust, for tests to compare against.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "chem/chemistry_model.hpp"
#include "chem/reaction_hook.hpp"
#include "core/random.hpp"

namespace cortex {

enum class EngineKind { kNextSubvolume, kDirect };

// Between advances an engine keeps no pending event times (waiting times are
// exponential, hence memoryless, so they are drawn afresh at the start of every
// advance): its whole state is the copies, the rate factors, the time and the random
// stream. That is what a checkpoint stores, and why setCopies/setRateFactor between
// advances are exact.
class ChemistryEngine {
 public:
  virtual ~ChemistryEngine() = default;

  // Fires every event up to t_end (s); afterwards time() == t_end.
  virtual void advance(double t_end) = 0;
  virtual double time() const = 0;

  // Copies of `species` in `compartment`. Setting them between advances updates only
  // the propensities that depend on them.
  virtual int copies(Index compartment, Index species) const = 0;
  virtual void setCopies(Index compartment, Index species, int n) = 0;
  // Scales reaction r's propensity in one compartment (mechanochemical feedback,
  // partial compartments); 1 by default.
  virtual void setRateFactor(Index reaction, Index compartment, double factor) = 0;

  // Confines `species` to one side of a membrane (thesis 2.2.4.2). Per compartment,
  // `volume` is the fraction of its volume on that side and `faces` the fractions of its
  // faces' areas (-x, +x, -y, +y, -z, +z) on that side; a shared face must get the same
  // value from both compartments (CompartmentSlices does this). Then the per-copy hop
  // rate through a face is D/h^2 * a_face / f_source (V_i d_ij symmetric, so the
  // stationary distribution is uniform in the confined volume); compartments with
  // f = 0 are inactive: no hops in or out. Propensities of reactions whose species are
  // confined (their first reactant, or first product for order 0, decides) scale by f
  // (order 0), 1 (order 1) or 1/f (order 2), per-site reactions (ReactionDef::per_site)
  // by f^-order, and all are 0 where f = 0. Copies sitting in a
  // compartment that becomes inactive move to the nearest active one (breadth first over
  // face neighbours, ties by compartment index and face order), so none is lost; throws
  // std::runtime_error if they have nowhere to go, std::invalid_argument for fractions
  // outside [0, 1] or of the wrong size. Call between advances; only compartments whose
  // rates changed are recomputed. Unconfined species (the default) behave as f = a = 1.
  virtual void setConfinement(Index species, const std::vector<double>& volume,
                              const std::vector<std::array<double, 6>>& faces) = 0;

  // Who carries out hooked reactions (not owned; must outlive the engine's advances).
  // A model with hooked reactions and no hook fires them as plain mass action.
  virtual void setReactionHook(ReactionHook* hook) = 0;

  virtual std::int64_t events() const = 0;
  // Events fired per reaction (index as in the model); diffusion hops counted apart.
  virtual const std::vector<std::int64_t>& reactionEvents() const = 0;
  virtual std::int64_t diffusionEvents() const = 0;

  // The random stream and clock, for checkpoints.
  virtual const RandomStream& random() const = 0;
  virtual void restore(const RandomStream& stream, double time, std::int64_t events,
                       const std::vector<std::int64_t>& reaction_events, std::int64_t diffusion_events) = 0;
};

// `copies` is compartment-major: copies[c * species + s].
std::unique_ptr<ChemistryEngine> makeChemistryEngine(EngineKind kind, const ChemistryModel& model,
                                                     const std::vector<int>& copies, std::uint64_t seed);

}  // namespace cortex
