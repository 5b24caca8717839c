// summary.json: the final state's observables (contract in docs/output.md).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "sim/system.hpp"

namespace cortex {

struct RunInfo {
  std::int64_t seed = 0;
  int threads = 1;
  double wall_seconds = 0.0;
};

nlohmann::json summarize(System& system, const RunInfo& info);
// Temporary file + rename: readers never see a half-written summary.
void writeJsonAtomically(const std::filesystem::path& file, const nlohmann::json& json);

}  // namespace cortex
