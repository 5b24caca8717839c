// The cytoskeleton at the start of a run: initial filaments placed from [[filaments]]
// (stream kFilamentPlacement, so adding filaments never changes the chemistry's initial
// copies), or the network stored in a checkpoint.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "filament/filament_network.hpp"
#include "filament/filament_placement.hpp"
#include "membrane/membrane.hpp"
#include "sim/system_state.hpp"

namespace cortex {

// box: the compartment grid's box (where filaments go without a [boundary]).
// regions: where entries with `inside` may go (placementRegions), one per entry.
std::unique_ptr<FilamentNetwork> buildFilamentNetwork(const FilamentConfig& config, const Vec3& box_min,
                                                      const Vec3& box_max, std::uint64_t seed,
                                                      const FilamentState* restored,
                                                      const std::vector<std::optional<PlacementRegion>>& regions = {});

// For each [[filaments]] entry with `inside`: the named closed membrane's bounding box and
// the test that a filament lies inside it, every point at least `margin` nm from it
// (which holds on to the membrane). InputError when no membrane has that name or it is
// open.
std::vector<std::optional<PlacementRegion>> placementRegions(const FilamentConfig& config,
                                                             const std::vector<std::unique_ptr<Membrane>>& membranes,
                                                             double margin);

// The state a checkpoint stores.
FilamentState filamentState(const FilamentNetwork& network);

}  // namespace cortex
