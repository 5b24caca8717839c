// A System from a parsed config: membranes, filaments, chemistry (with the filament
// reactions appended to the config's own) wired together, fresh or from a checkpoint.
#pragma once

#include <memory>

#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "sim/system.hpp"

namespace cortex {

// Throws InputError when the checkpoint does not match the config.
std::unique_ptr<System> buildSystem(const Config& config, const Checkpoint* restored);

}  // namespace cortex
