// Gillespie's direct method over every channel, kept simple enough to trust: one flat
// propensity array (reactions of every subvolume, then one hop channel per directed edge
// and species), the total summed afresh before every event, a linear search to pick the
// channel, and all channels of the touched subvolumes recomputed. O(channels) per
// event: for tests and as a benchmark baseline, not for real runs.
#pragma once

#include <vector>

#include "chem/engine_base.hpp"

namespace cortex {

class DirectMethodEngine final : public EngineBase {
 public:
  DirectMethodEngine(const ChemistryModel& model, const std::vector<int>& copies, std::uint64_t seed);

  void advance(double t_end) override;
  void setCopies(Index subvolume, Index species, int n) override;

 private:
  void setRateFactor(Index reaction, Index subvolume, double factor) override;
  void recompute(Index i);
  // Recomputes i and, if copies of s changed there, the surface subvolumes reading them.
  void touch(Index i, Index s);
  void refreshSubvolume(Index i) override { recompute(i); }
  void relaidOut() override;
  double sum() const;
  double totalRate() const override { return sum(); }
  void fire(std::size_t channel);

  std::vector<Index> edge_source_;  // per directed edge
  std::vector<double> propensity_;  // [i * R + r], then hops at N * R + e * S + s
};

}  // namespace cortex
