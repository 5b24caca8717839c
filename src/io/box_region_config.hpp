// Reading an axis-aligned box, `region = { min = [x, y, z], max = [x, y, z] }` (nm), the
// one shape of a region in configs: where a reaction fires, where a surface species starts.
#pragma once

#include <optional>

#include "io/config_reader.hpp"
#include "sim/run_config.hpp"

namespace cortex {

// Empty when `parent` has no table `key`; fails (naming it) unless min < max on every axis.
std::optional<BoxRegion> readBoxRegion(const ConfigReader& parent, const std::string& key);

}  // namespace cortex
