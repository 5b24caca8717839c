#include "filament/filament_terms.hpp"

#include "filament/boundary_energy.hpp"
#include "filament/branch_energy.hpp"
#include "filament/excluded_volume_energy.hpp"
#include "filament/filament_bending_energy.hpp"
#include "filament/stretching_energy.hpp"

namespace cortex {

// Neighbour-list skin of the excluded volume (nm): beads move a few nm per minimization,
// so a 40 nm skin rebuilds the list rarely within one.
constexpr double kExclusionSkin = 40.0;

FilamentTerms addFilamentTerms(const FilamentNetwork& network, ForceField& ff) {
  const FilamentLayout& layout = network.layout();
  const FilamentConfig& config = network.config();
  FilamentTerms terms;
  ff.add(std::make_unique<FilamentStretchingEnergy>(layout, config.types));
  ff.add(std::make_unique<FilamentBendingEnergy>(layout, config.types));
  ff.add(std::make_unique<CylinderExclusionEnergy>(layout, config.types, kExclusionSkin));
  if (config.boundary) ff.add(std::make_unique<BoundaryRepulsionEnergy>(layout, *config.boundary));
  if (!config.linkers.empty()) terms.linkers = &ff.add(std::make_unique<SpringEnergy>(layout, layout.linkers, "linkers"));
  if (!config.motors.empty()) terms.motors = &ff.add(std::make_unique<SpringEnergy>(layout, layout.motors, "motors"));
  if (!config.branchers.empty()) ff.add(std::make_unique<BranchEnergy>(layout));
  return terms;
}

}  // namespace cortex
