// Membrane confinement of 3D species (thesis 2.2.4.2): slices the membranes that confine
// species and hands each species the fractions of its side to the engine. Recomputed
// from the membranes alone, so a checkpoint needs to store nothing for it.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "sim/system.hpp"

namespace cortex {

struct SideFractions {
  std::vector<double> volume;                // per compartment
  std::vector<std::array<double, 6>> faces;  // per compartment, -x, +x, -y, +y, -z, +z
};

// Per species: the fractions of its side, or nothing when unconfined. Each confining
// membrane is sliced once. Throws InputError for a membrane that does not exist or is
// not closed (loaded meshes are only known to be closed once read).
std::vector<std::optional<SideFractions>> speciesFractions(const System& system, const std::vector<SpeciesSide>& sides,
                                                           const CompartmentGrid& grid);

// Re-slices and applies to the engine: species confinement, and the rate factors of
// reactions restricted to a box or a side of a membrane. Called when the engine is
// built or restored and after every relaxation (membranes move).
void confineChemistry(System& system);

}  // namespace cortex
