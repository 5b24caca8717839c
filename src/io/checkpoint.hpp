// checkpoint.h5: everything needed to continue a run bit-identically — the effective
// config, the clock, the counters, and each membrane's mesh and reference state.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "sim/filament_builder.hpp"
#include "sim/membrane_builder.hpp"
#include "sim/system.hpp"

namespace cortex {

struct CheckpointHeader {
  std::string config_toml;   // effective config (after --set overrides)
  std::string config_source; // original file name, for messages
  std::string base_dir;      // directory relative mesh paths resolve against
  std::int64_t next_snapshot = 0;
};

// The engine's whole state between advances (chemistry_engine.hpp).
struct ChemistryState {
  std::vector<int> copies;  // compartment-major
  std::uint64_t random_counter = 0;
  int random_used = 4;
  double time = 0.0;
  std::int64_t events = 0, diffusion_events = 0;
  std::vector<std::int64_t> reaction_events;
};

struct Checkpoint {
  CheckpointHeader header;
  double time = 0.0;
  std::int64_t step = 0;
  RunCounters counters;
  std::int64_t force_evaluations = 0, energy_evaluations = 0;
  std::map<std::string, MembraneState> membranes;
  std::optional<ChemistryState> chemistry;
  std::optional<FilamentState> filaments;
};

// Writes atomically (a temporary file renamed over the old one), so a crash never
// leaves a half-written checkpoint.
void writeCheckpoint(const std::filesystem::path& file, const CheckpointHeader& header, const System& system);
// Throws InputError if the file is missing or not a cortex checkpoint.
Checkpoint readCheckpoint(const std::filesystem::path& file);

}  // namespace cortex
