// The cytoskeleton at the start of a run: initial filaments placed from [[filaments]]
// (stream kFilamentPlacement, so adding filaments never changes the chemistry's initial
// copies), or the network stored in a checkpoint.
#pragma once

#include <memory>
#include <optional>

#include "filament/filament_network.hpp"
#include "sim/system_state.hpp"

namespace cortex {

// box: the compartment grid's box (where filaments go without a [boundary]).
std::unique_ptr<FilamentNetwork> buildFilamentNetwork(const FilamentConfig& config, const Vec3& box_min,
                                                      const Vec3& box_max, std::uint64_t seed,
                                                      const FilamentState* restored);

// The state a checkpoint stores.
FilamentState filamentState(const FilamentNetwork& network);

}  // namespace cortex
