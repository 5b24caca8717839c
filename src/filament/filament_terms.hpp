// The energy terms of the cytoskeleton, from the network's parameters: the one place a
// new filament term is registered.
#pragma once

#include "filament/filament_network.hpp"
#include "filament/spring_energy.hpp"
#include "mech/force_field.hpp"

namespace cortex {

// The terms whose state the mechanochemical feedback reads (tensions of bound proteins).
struct FilamentTerms {
  const SpringEnergy* linkers = nullptr;
  const SpringEnergy* motors = nullptr;
};

// Adds stretching, bending and excluded volume, and the walls, linkers, motors and
// branch joints the configuration has.
FilamentTerms addFilamentTerms(const FilamentNetwork& network, ForceField& force_field);

}  // namespace cortex
