// Creates the chemistry engine a config asks for, with the initial copies spread
// uniformly at random in volume (stream kInitialConditions): over the compartments, or,
// for a confined species, over its side of the membrane (compartments weighted by their
// volume fraction there).
#pragma once

#include <memory>

#include "sim/run_config.hpp"

namespace cortex {

// `volume_weights` per species: empty for uniform over the compartments, else one
// non-negative weight per compartment (not all zero when the species has copies).
std::vector<int> initialCopies(const ChemistryConfig& config, std::uint64_t seed,
                               const std::vector<std::vector<double>>& volume_weights = {});
std::unique_ptr<ChemistryEngine> buildChemistry(const ChemistryConfig& config, std::uint64_t seed,
                                                const std::vector<std::vector<double>>& volume_weights = {});

}  // namespace cortex
