// A key that names a closed membrane: `inside` / `outside` of a [[species]] and `inside`
// of a [[filaments]] entry.
#pragma once

#include <string>
#include <vector>

#include "io/config_reader.hpp"
#include "sim/run_config.hpp"

namespace cortex {

// The membrane named by `key` of table `r`. Errors (file, key) when no [[membrane]] has
// that name or it is a plane (open: no inside); a loaded mesh is checked once read
// (closedMembrane in sim/membrane_builder.hpp).
std::string readClosedMembraneName(const ConfigReader& r, const std::string& key,
                                   const std::vector<MembraneConfig>& membranes);

}  // namespace cortex
