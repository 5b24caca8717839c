// Small configs for the hostile-input tests (test_hostile_input.cpp,
// test_hostile_output_folders.cpp), and the check that a config is refused alike by
// `check` and `run` before anything is written.
#pragma once

#include <string>

#include "app/cli_helpers.hpp"

namespace cortex::cli_test {

inline const char* kVesicle = R"([simulation]
end_time = 0.02
chemistry_window = 0.01
snapshot_interval = 0.01

[[membrane]]
name = "vesicle"
shape = "sphere"
radius = 200.0
mesh_size = 40.0
)";

inline const char* kSpecies = R"([simulation]
end_time = 0.02
chemistry_window = 0.01
[compartments]
size = 100.0
shape = [2, 2, 2]
[[species]]
name = "A"
diffusion = 1.0e6
copies = 10
)";

inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

inline void expectRefusedInCheckAndRun(const TempDir& dir, const std::string& text, const std::string& key,
                                const std::string& what) {
  const fs::path config = writeConfig(dir.path(), text, "hostile.toml");
  const RunResult check = runCortex({"check", config.string()}, dir.path());
  EXPECT_EQ(check.exit_code, 2) << what << "\n" << describe(check);
  EXPECT_NE(check.err.find(key), std::string::npos) << what << ": the message names " << key << "\n" << describe(check);
  const fs::path out = dir / "out";
  const RunResult run = runConfig(config, out, {"--overwrite"}, dir.path());
  EXPECT_EQ(run.exit_code, 2) << what << "\n" << describe(run);
  EXPECT_FALSE(fs::exists(out / "snapshots" / "000000.h5")) << what << ": nothing is written";
}

}  // namespace cortex::cli_test
