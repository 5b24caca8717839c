// What both engine implementations share: the compiled network, the grid faces, the
// copies, and the clock, stream and counters that make up a checkpoint.
#pragma once

#include <limits>

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
  void setReactionHook(ReactionHook* hook) override { hook_ = hook; }
  void restore(const RandomStream& stream, double time, std::int64_t events,
               const std::vector<std::int64_t>& reaction_events, std::int64_t diffusion_events) override;
  // Stores the confinement, relocates stranded copies, then lets the engine recompute
  // the compartments whose rates changed (refreshCompartment).
  void setConfinement(Index species, const std::vector<double>& volume,
                      const std::vector<std::array<double, 6>>& faces) override;

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
  // Copy numbers are 32-bit: a reaction that would push one past 2^31 - 1 stops the run
  // (RunError) instead of wrapping around.
  void checkGrowth(int n, int delta, Index compartment, Index species) const {
    if (delta > 0 && n > std::numeric_limits<int>::max() - delta) growthOverflow(compartment, species);
  }
  [[noreturn]] void growthOverflow(Index compartment, Index species) const;

  // Recomputes every propensity of compartment c from copies_ and the rates.
  virtual void refreshCompartment(Index c) = 0;

  // Lets the hook carry out reaction r in c if it is hooked; false: the event is void.
  bool hookAccepts(Index r, Index c) { return !hook_ || !net_.hooked[r] || hook_->fired(r, c, *this, rng_); }

  bool confined(Index species) const { return confined_[species] != 0; }
  // Per-copy hop rate of a confined species out of c, in total and through face f.
  double hopOut(Index c, Index s) const { return hop_out_[static_cast<std::size_t>(c) * S_ + s]; }
  const double* faceRates(Index c, Index s) const { return &face_rate_[(static_cast<std::size_t>(c) * S_ + s) * 6]; }
  // Factor by which confinement scales reaction r's propensity in compartment c.
  double confinementScale(Index c, Index r) const {
    const Index s = scale_species_[r];
    if (s < 0) return 1.0;
    const double f = volume_[static_cast<std::size_t>(c) * S_ + s];
    if (!(f > 0.0)) return 0.0;
    const int order = reaction_order_[r];
    // A per-site propensity (an end, a pair of sites) is k prod [X], each concentration
    // n / (f V), whatever the order.
    if (net_.perSite[r]) return order == 0 ? 1.0 : order == 1 ? 1.0 / f : 1.0 / (f * f);
    return order == 0 ? f : order == 2 ? 1.0 / f : 1.0;
  }
  bool active(Index c, Index s) const { return !confined(s) || volume_[static_cast<std::size_t>(c) * S_ + s] > 0.0; }

  ReactionNetwork net_;
  GridFaces faces_;
  Index S_, R_, C_;          // species, reactions, compartments
  std::vector<int> copies_;  // compartment-major: copies_[c * S_ + s]
  RandomStream rng_;
  double time_ = 0.0;
  std::int64_t events_ = 0;
  std::vector<std::int64_t> reaction_events_;
  std::int64_t diffusion_events_ = 0;
  ReactionHook* hook_ = nullptr;

 private:
  // Moves copies of s out of inactive compartments; returns the compartments touched.
  void relocate(Index s, std::vector<char>& dirty);

  std::vector<char> confined_;         // per species
  std::vector<Index> side_species_;    // per reaction: the species whose side it lives on
  std::vector<int> reaction_order_;    // per reaction
  std::vector<Index> scale_species_;   // per reaction: side_species_ once confined, else -1
  // Allocated at the first setConfinement: [c * S + s] and [(c * S + s) * 6 + face].
  std::vector<double> volume_, hop_out_, face_rate_;
};

}  // namespace cortex
