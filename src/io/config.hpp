// Reading the run configuration from TOML: every key validated in one place, errors
// naming file, line and key. Units and keys in docs/config.md.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sim/run_config.hpp"

namespace cortex {

// Reads a config file, applies "key.path=value" overrides, validates everything.
// Throws InputError naming file, line and key on any problem.
Config loadConfig(const std::filesystem::path& file, const std::vector<std::string>& overrides);
// The same from TOML text (checkpoints store the effective config this way);
// relative mesh paths resolve against base_dir.
Config parseConfig(const std::string& toml_text, const std::string& source,
                   const std::filesystem::path& base_dir, const std::vector<std::string>& overrides);

}  // namespace cortex
