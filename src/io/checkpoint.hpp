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
  std::string run_id;        // names the run (its first config, seed and version); resumes keep it
};

struct Checkpoint {
  CheckpointHeader header;
  SystemState state;
};

// Built in memory and written atomically (writeFileAtomically), so neither a crash nor a
// full disk leaves a half-written checkpoint; its first 512 bytes (an HDF5 user block)
// hold the format and a checksum of the rest.
void writeCheckpoint(const std::filesystem::path& file, const CheckpointHeader& header, const SystemState& state);
// Throws InputError if the file is missing, not a cortex checkpoint of this format, or
// damaged (checksum mismatch).
Checkpoint readCheckpoint(const std::filesystem::path& file);

}  // namespace cortex
