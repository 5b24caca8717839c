// The chemistry of a System: its model (the grid's subvolumes, the config's species and
// reactions, then the reactions modules append) and an engine with the initial copies
// spread uniformly at random in volume (stream kInitialConditions): over the
// compartments, or, for a confined species, over its side of the membrane (compartments
// weighted by their volume fraction there).
#pragma once

#include <memory>

#include "sim/run_config.hpp"

namespace cortex {

// The model with the config's own reactions only, owned by "config".
ChemistryModel chemistryModel(const ChemistryConfig& config);

// `volume_weights` per species: empty for uniform over the compartments, else one
// non-negative weight per compartment (not all zero when the species has copies).
std::vector<int> initialCopies(const ChemistryConfig& config, std::uint64_t seed,
                               const std::vector<std::vector<double>>& volume_weights = {});

}  // namespace cortex
