#include "interact/membrane_end_loads.hpp"

namespace cortex {

void MembraneEndLoads::update() {
  cells_.clear();
  for (const MembraneBeadExclusion* term : terms_) cells_.push_back(term->heldCells());
}

Vec3 MembraneEndLoads::forceAt(Index /*filament*/, const Vec3& point, bool plus_end) const {
  Vec3 force = Vec3::Zero();
  for (std::size_t i = 0; i < terms_.size() && i < cells_.size(); ++i)
    if (terms_[i]->params().beads != ExclusionBeads::kPlusEnds || plus_end)
      force += terms_[i]->forceAt(point, cells_[i]);
  return force;
}

}  // namespace cortex
