// What both engine implementations share: the compiled network, the grid faces, the
// copies, and the clock, stream and counters that make up a checkpoint.
#pragma once

#include "chem/chemistry_engine.hpp"
#include "chem/grid_faces.hpp"
#include "chem/reaction_network.hpp"

namespace cortex {

class EngineBase : public ChemistryEngine {
 public:
  double time() const override { return time_; }
  int copies(Index compartment, Index species) const override { return copies_[slot(compartment, species)]; }
  std::int64_t events() const override { return events_; }
  const std::vector<std::int64_t>& reactionEvents() const override { return reaction_events_; }
  std::int64_t diffusionEvents() const override { return diffusion_events_; }
  const RandomStream& random() const override { return rng_; }
  void restore(const RandomStream& stream, double time, std::int64_t events,
               const std::vector<std::int64_t>& reaction_events, std::int64_t diffusion_events) override;

 protected:
  // Throws InputError for an invalid model or negative copies, std::invalid_argument
  // when `copies` does not have compartments * species entries.
  EngineBase(const ChemistryModel& model, const std::vector<int>& copies, std::uint64_t seed);

  // Index of (compartment, species) in copies_; throws std::out_of_range.
  std::size_t slot(Index compartment, Index species) const;
  // Checks the arguments of setCopies / setRateFactor; throws std::out_of_range or
  // std::invalid_argument.
  void checkCopies(Index compartment, Index species, int n) const;
  void checkRateFactor(Index reaction, Index compartment, double factor) const;

  ReactionNetwork net_;
  GridFaces faces_;
  Index S_, R_, C_;          // species, reactions, compartments
  std::vector<int> copies_;  // compartment-major: copies_[c * S_ + s]
  RandomStream rng_;
  double time_ = 0.0;
  std::int64_t events_ = 0;
  std::vector<std::int64_t> reaction_events_;
  std::int64_t diffusion_events_ = 0;
};

}  // namespace cortex
