#include "chem/chemistry_engine.hpp"

#include <stdexcept>

#include "chem/direct_method.hpp"
#include "chem/next_subvolume.hpp"

namespace cortex {

void RateFactors::set(Index reaction, Index subvolume, double factor) const {
  if (!engine_ || !range_.contains(reaction))
    throw std::out_of_range("rate factors of \"" + range_.owner + "\": reaction " + std::to_string(reaction) +
                            " is not theirs");
  engine_->setRateFactor(reaction, subvolume, factor);
}

std::unique_ptr<ChemistryEngine> makeChemistryEngine(EngineKind kind, const ChemistryModel& model,
                                                     const std::vector<int>& copies, std::uint64_t seed) {
  if (kind == EngineKind::kDirect) return std::make_unique<DirectMethodEngine>(model, copies, seed);
  return std::make_unique<NextSubvolumeEngine>(model, copies, seed);
}

}  // namespace cortex
