// The next-subvolume method (Elf & Ehrenberg 2004): every compartment's reactions and
// hops are summed into one propensity, and a priority queue orders the compartments by
// their next event time, so an event costs O(log compartments) however many channels
// the grid has. The compartment that fired draws a fresh exponential; a hop's
// destination, whose propensity changed without firing, has its pending time rescaled
// (Gibson & Bruck 2000) and draws nothing.
//
// Layout (the work is keeping the event loop in cache): copies, propensities and rate
// constants are compartment-major flat arrays; per compartment one 24-byte record holds
// the reaction and diffusion sums; reactions are also summed in blocks of 32 so that
// picking one among many costs a scan of blocks plus one block; the queue is two-level
// (EventQueue). Sums are updated incrementally by differences of exactly recomputed
// propensities, and rebuilt from scratch at the start of every advance: that bounds
// rounding drift to one window, and makes an engine restored from a checkpoint
// bit-identical to the one that wrote it.
#pragma once

#include <algorithm>
#include <vector>

#include "chem/engine_base.hpp"
#include "chem/event_queue.hpp"

namespace cortex {

class NextSubvolumeEngine final : public EngineBase {
 public:
  NextSubvolumeEngine(const ChemistryModel& model, const std::vector<int>& copies, std::uint64_t seed);

  void advance(double t_end) override;
  void setCopies(Index compartment, Index species, int n) override;
  void setRateFactor(Index reaction, Index compartment, double factor) override;

 private:
  static constexpr Index kBlock = 32;  // reactions per partial sum

  struct Subvolume {
    double reactions = 0.0;  // sum of reaction propensities
    double diffusion = 0.0;  // sum_s hopOutOf(c, s) * n_s
    int faces = 0;           // faces with a neighbour
  };
  static double total(const Subvolume& v) { return std::max(v.reactions, 0.0) + std::max(v.diffusion, 0.0); }

  void refresh(Index c);
  void refreshCompartment(Index c) override { refresh(c); }
  // Per-copy hop rate of species s out of c: all faces alike unless s is confined.
  double hopOutOf(Index c, Index s) const { return confined(s) ? hopOut(c, s) : sub_[c].faces * net_.hopRate[s]; }
  void setPropensity(Index c, Index r);
  void changeCopies(Index c, Index s, int delta);
  void fire(Index c, double t);
  Index pickReaction(Index c, double x) const;
  void react(Index c, Index r);
  bool hop(Index c, double x);
  void reschedule(Index c, double t);
  // Applies `change` to compartment c's propensities; during an advance, a compartment
  // other than the one firing keeps its pending time, rescaled to the new propensity
  // (Gibson & Bruck 2000) instead of drawing a new random number.
  template <class Change>
  void changeSubvolume(Index c, Change&& change);

  Index blocks_;                    // reaction blocks per compartment
  std::vector<double> rate_;        // [c * R + r]: rate factor * stochastic rate constant
  std::vector<double> propensity_;  // [c * R + r]
  std::vector<double> block_sum_;   // [c * blocks_ + b]
  std::vector<Subvolume> sub_;
  bool advancing_ = false;
  Index firing_ = -1;   // compartment being fired, during an advance
  double now_ = 0.0;    // its event time
  std::vector<double> first_times_;  // scratch for the heap rebuilt at each advance
  EventQueue heap_;
};

}  // namespace cortex
