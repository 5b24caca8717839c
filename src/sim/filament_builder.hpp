// The cytoskeleton at the start of a run: initial filaments placed from [[filaments]]
// (stream kFilamentPlacement, so adding filaments never changes the chemistry's initial
// copies), or the network stored in a checkpoint.
#pragma once

#include <memory>
#include <optional>

#include "filament/filament_network.hpp"

namespace cortex {

// The network's whole state, as a checkpoint stores it.
struct FilamentState {
  std::vector<Filament> filaments;
  std::vector<Binding> linkers, motors;
  std::vector<Branch> branches;
};

// box: the compartment grid's box (where filaments go without a [boundary]).
std::unique_ptr<FilamentNetwork> buildFilamentNetwork(const FilamentConfig& config, const Vec3& box_min,
                                                      const Vec3& box_max, std::uint64_t seed,
                                                      const FilamentState* restored);

}  // namespace cortex
