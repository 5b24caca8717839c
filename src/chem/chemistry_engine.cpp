#include "chem/chemistry_engine.hpp"

#include "chem/direct_method.hpp"
#include "chem/next_subvolume.hpp"

namespace cortex {

std::unique_ptr<ChemistryEngine> makeChemistryEngine(EngineKind kind, const ChemistryModel& model,
                                                     const std::vector<int>& copies, std::uint64_t seed) {
  if (kind == EngineKind::kDirect) return std::make_unique<DirectMethodEngine>(model, copies, seed);
  return std::make_unique<NextSubvolumeEngine>(model, copies, seed);
}

}  // namespace cortex
