// Reading [[filament_type]], [[filaments]], [boundary], [[linker]], [[motor]] and
// [[brancher]]: the filament part of a config (docs/config.md, Filaments).
#pragma once

#include <optional>

#include "filament/filament_params.hpp"
#include "io/config_reader.hpp"
#include "sim/run_config.hpp"

namespace cortex {

// Empty when the config has no [[filament_type]] (then the other filament tables are
// errors: they would be ignored). Species names resolve against chemistry's
// [[species]]; the boundary box defaults to the compartment grid's box; `membranes`
// resolves the inside key of [[filaments]]; stiffnesses are checked against
// `force_tolerance` (pN, io/resolvable_forces.hpp).
std::optional<FilamentConfig> readFilaments(const ConfigReader& root, const std::optional<ChemistryConfig>& chemistry,
                                            const std::vector<MembraneConfig>& membranes, double force_tolerance);

}  // namespace cortex
