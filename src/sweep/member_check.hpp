// Every member of a sweep validated before any runs, as `cortex check` would validate it
// (config keys, meshes, placement, chemistry load): a bad grid point is refused up front
// with exit code 2, never discovered hours into the sweep.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sweep/sweep_spec.hpp"

namespace cortex {

// What a sweep keeps of each checked member: two numbers, not its config text (4 KB), so
// that the documented 10⁶ members fit in memory. Its overrides are memberOverrides again.
struct CheckedMember {
  std::int64_t seed = 0;          // its effective simulation.seed
  std::uint64_t config_hash = 0;  // fnv1a64 of its whole config, as its run stores it in trajectory.h5
};

// Throws InputError naming the sweep file, the member and its settings, and the problem.
std::vector<CheckedMember> checkMembers(const SweepSpec& spec);

// "member 3 (membrane.0.bending_modulus=20.0, simulation.seed=2)"
std::string describeMember(const SweepSpec& spec, std::size_t index);

// `cortex check SWEEP.toml`: every member checked; a one-line report.
std::string checkSweep(const std::filesystem::path& file);

}  // namespace cortex
