// Gillespie's direct method over every channel of the grid, kept simple enough to trust:
// one flat propensity array (reactions of every compartment, then one hop channel per
// compartment, species and face), the total summed afresh before every event, a linear
// search to pick the channel, and all channels of the touched compartments recomputed.
// O(channels) per event: for tests and as a benchmark baseline, not for real runs.
#pragma once

#include <vector>

#include "chem/engine_base.hpp"

namespace cortex {

class DirectMethodEngine final : public EngineBase {
 public:
  DirectMethodEngine(const ChemistryModel& model, const std::vector<int>& copies, std::uint64_t seed);

  void advance(double t_end) override;
  void setCopies(Index compartment, Index species, int n) override;
  void setRateFactor(Index reaction, Index compartment, double factor) override;

 private:
  void recompute(Index c);
  void refreshCompartment(Index c) override { recompute(c); }
  double sum() const;
  void fire(std::size_t channel);

  std::vector<double> factor_;      // [c * R + r]
  std::vector<double> propensity_;  // [c * R + r], then hops at C * R + (c * S + s) * 6 + face
};

}  // namespace cortex
