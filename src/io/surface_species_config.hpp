// Reading [[membrane.species]]: protein species living on a membrane (thesis chapter 3).
#pragma once

#include "io/config_reader.hpp"
#include "sim/run_config.hpp"

namespace cortex {

// The species of one [[membrane]] table (none without the key).
std::vector<SurfaceSpeciesConfig> readSurfaceSpecies(const ConfigReader& membrane);

}  // namespace cortex
