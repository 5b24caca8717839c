// Creates the chemistry engine a config asks for, with the initial copies spread
// uniformly at random over the compartments (stream kInitialConditions).
#pragma once

#include <memory>

#include "sim/run_config.hpp"

namespace cortex {

std::vector<int> initialCopies(const ChemistryConfig& config, std::uint64_t seed);
std::unique_ptr<ChemistryEngine> buildChemistry(const ChemistryConfig& config, std::uint64_t seed);

}  // namespace cortex
