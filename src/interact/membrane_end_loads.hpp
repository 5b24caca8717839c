// The membranes' push on filament ends between relaxations (filament/end_load_probe.hpp):
// the membrane–bead excluded volume of every coupled membrane, evaluated at an end where
// it now is, with the membranes where the last relaxation left them.
#pragma once

#include <vector>

#include "filament/end_load_probe.hpp"
#include "interact/membrane_bead_exclusion.hpp"
#include "interact/triangle_cells.hpp"

namespace cortex {

class MembraneEndLoads final : public EndLoadProbe {
 public:
  explicit MembraneEndLoads(std::vector<const MembraneBeadExclusion*> terms) : terms_(std::move(terms)) {}
  // After every relaxation (the membranes moved or were remeshed): their triangles as
  // they now stand.
  void update() override;
  Vec3 forceAt(Index filament, const Vec3& point, bool plus_end) const override;

 private:
  std::vector<const MembraneBeadExclusion*> terms_;
  std::vector<TriangleCells> cells_;  // per term
};

}  // namespace cortex
