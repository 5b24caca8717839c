// Reading [compartments], [chemistry], [[species]] and [[reaction]]: the 3D
// reaction-diffusion part of a config.
#pragma once

#include <optional>

#include "io/config_reader.hpp"
#include "sim/run_config.hpp"

namespace cortex {

// Empty when the config has no [[species]] (then [[reaction]] and [compartments] are
// errors: they would be ignored).
// `membranes` resolves the inside / outside keys of [[species]].
std::optional<ChemistryConfig> readChemistry(const ConfigReader& root, const std::vector<MembraneConfig>& membranes);

}  // namespace cortex
