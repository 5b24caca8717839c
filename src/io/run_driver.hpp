// Everything `cortex run` and `cortex check` do between parsing the command line and
// returning: config, output folder, logging, writers, the loop, the summary.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sim/simulation.hpp"

namespace cortex {

struct RunRequest {
  std::filesystem::path config;        // fresh run
  std::filesystem::path resume_dir;    // or: continue the run in this folder
  std::filesystem::path output_dir;    // fresh run; default <config stem>_out
  std::vector<std::string> overrides;  // --set key.path=value
  std::optional<std::int64_t> seed;    // --seed
  int threads = 1;
  bool quiet = false;                  // no progress on stderr
  double progress_interval = 30.0;     // s between progress lines when stderr is not a terminal; 0: none
  bool overwrite = false;              // a fresh run may replace an earlier run's results
};

// Throws InputError (bad input) or RunError (failure during the run). kStopped: a signal
// stopped the run after a checkpoint (exit code 3; resume it).
RunOutcome runSimulation(const RunRequest& request);
// Validates a config (and builds its meshes) without running; returns a one-line report.
std::string checkConfig(const std::filesystem::path& config, const std::vector<std::string>& overrides);
// The same for a config already loaded from `file` (a sweep checks each member's this way).
std::string checkLoadedConfig(const Config& config, const std::filesystem::path& file);

}  // namespace cortex
