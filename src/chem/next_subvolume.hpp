// The next-subvolume method (Elf & Ehrenberg 2004): every subvolume's reactions and hops
// are summed into one propensity, and a priority queue orders the subvolumes by their
// next event time, so an event costs O(log subvolumes) however many channels the graph
// has. The subvolume that fired draws a fresh exponential; one whose propensity changed
// without firing (a hop's destination, the compartment holding a surface subvolume, the
// surface subvolumes a compartment holds) has its pending time rescaled (Gibson & Bruck
// 2000) and draws nothing.
//
// Layout (the work is keeping the event loop in cache): copies, propensities and rate
// constants are subvolume-major flat arrays; per subvolume one 24-byte record holds the
// reaction and diffusion sums and where its edges are; reactions are also summed in
// blocks of 32 so that picking one among many costs a scan of blocks plus one block; the
// queue is two-level (EventQueue). Sums are updated incrementally by differences of
// exactly recomputed propensities, and rebuilt from scratch at the start of every
// advance: that bounds rounding drift to one window, and makes an engine restored from a
// checkpoint bit-identical to the one that wrote it.
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
  void setCopies(Index subvolume, Index species, int n) override;

 private:
  static constexpr Index kBlock = 32;  // reactions per partial sum

  // What the event loop reads of a subvolume, in one 24-byte record.
  struct Subvolume {
    double reactions = 0.0;  // sum of reaction propensities
    double diffusion = 0.0;  // sum_s hopOutOf(i, s) * n_s
    Index first_edge = 0;
    std::uint16_t degree = 0;
    std::uint8_t region = 0;
    std::uint8_t faces = 0;  // on a lattice: bit f set when face f (-x, +x, ...) has a neighbour
  };
  // Destination of a hop along subvolume i's k-th edge. On a lattice it is arithmetic:
  // a look-up in the edge array is a cache miss on large grids (half of a hop's cost).
  Index neighbour(Index i, const Subvolume& v, Index k) const;
  static double total(const Subvolume& v) { return std::max(v.reactions, 0.0) + std::max(v.diffusion, 0.0); }

  void setRateFactor(Index reaction, Index subvolume, double factor) override;
  void refresh(Index i);
  // sum_s hopOutOf(i, s) * n_s, from scratch.
  double diffusionSum(Index i) const;
  // After copies of interacting species s changed in a and b (EngineBase::interactionChanged).
  void interactionMoved(Index s, Index a, Index b);
  void refreshSubvolume(Index i) override { refresh(i); }
  void relaidOut() override;
  double totalRate() const override;
  // EngineBase::hopOutOf from the record the loop has at hand.
  double hopOutOf(Index i, Index s) const {
    return weighted(s) ? hopOut(i, s) : sub_[i].degree * hopRate(s);
  }
  void setPropensity(Index i, Index r);
  // Changes the copies of s in i by delta and every propensity that reads them, there
  // and in the surface subvolumes i holds. Inline, with the readers out of line: a
  // species no reaction reads (pure diffusion) pays three loads and no call.
  void changeCopies(Index i, Index s, int delta) {
    copies_[static_cast<std::size_t>(i) * S_ + s] += delta;
    sub_[i].diffusion += delta * hopOutOf(i, s);
    if (read_[s]) updateReaders(i, s);
  }
  // The propensities reading species s in i, and in the surface subvolumes i holds.
  void updateReaders(Index i, Index s);
  void fire(Index i, double t);
  Index pickReaction(Index i, double x) const;
  // Reaction r's changes in subvolume i itself and the propensities there that read them;
  // true when a changed species is read by the surface subvolumes i holds.
  bool changeLocally(Index i, Index r);
  // Reaction r's changes of 3D species in h, the holder of the surface subvolume where it
  // fired, and everything that reads them.
  void changeHeld(Index h, Index r);
  // The fields of the interacting species reaction r changed in subvolume i.
  void moveInteracting(Index i, Index r);
  void react(Index i, Index r);
  bool fireBinding(Index h, Index r);
  // kMissed: rounding put x past the last channel; kCrowded: the destination is full
  // (SpeciesDef::footprint), a void event.
  enum class HopOutcome { kMoved, kCrowded, kMissed };
  static constexpr Index kCrowdedHop = -2;  // fire()'s marker of a crowded hop
  HopOutcome hop(Index i, double x);
  void reschedule(Index i, double t);
  // Applies `change` to subvolume i's propensities; during an advance, a subvolume other
  // than the one firing keeps its pending time, rescaled to the new propensity (Gibson &
  // Bruck 2000) instead of drawing a new random number.
  template <class Change>
  void changeSubvolume(Index i, Change&& change);

  Index blocks_;                    // reaction blocks per subvolume
  bool lattice_ = false;            // the 3D subvolumes are a lattice
  std::array<Index, 6> lattice_step_{};  // index offset through each face
  std::vector<double> rate_;        // [i * R + r]: rate factor * propensity constant
  std::vector<double> propensity_;  // [i * R + r]
  std::vector<double> block_sum_;   // [i * blocks_ + b]
  std::vector<Subvolume> sub_;
  std::vector<std::uint8_t> read_;  // per species: some reaction reads its copies
  bool advancing_ = false;
  Index firing_ = -1;   // subvolume being fired, during an advance
  double now_ = 0.0;    // its event time
  std::vector<double> first_times_;  // scratch for the heap rebuilt at each advance
  EventQueue heap_;
};

}  // namespace cortex
