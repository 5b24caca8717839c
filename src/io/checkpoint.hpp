// checkpoint.h5: everything needed to continue a run bit-identically — the effective
// config, where the trajectory stands, and the System's whole state (SystemState).
#pragma once

#include <filesystem>
#include <string>

#include "sim/system_state.hpp"

namespace cortex {

struct CheckpointHeader {
  std::string config_toml;   // effective config (after --set overrides)
  std::string config_source; // original file name, for messages
  std::string base_dir;      // directory relative mesh paths resolve against
  std::int64_t next_snapshot = 0;
};

struct Checkpoint {
  CheckpointHeader header;
  SystemState state;
};

// Writes atomically (a temporary file renamed over the old one), so a crash never
// leaves a half-written checkpoint.
void writeCheckpoint(const std::filesystem::path& file, const CheckpointHeader& header, const SystemState& state);
// Throws InputError if the file is missing or not a cortex checkpoint.
Checkpoint readCheckpoint(const std::filesystem::path& file);

}  // namespace cortex
