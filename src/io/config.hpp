// The whole run configuration, parsed from TOML into typed parameter structs and
// validated in one place (config.cpp). Units as in docs/config.md.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "mech/minimizer.hpp"
#include "membrane/membrane.hpp"

namespace cortex {

struct SimulationConfig {
  std::int64_t seed = 1;
  double end_time = 0.0;            // s
  double chemistry_window = 0.01;   // s between mechanical relaxations
  double snapshot_interval = 0.1;   // s
  double checkpoint_interval = 0.0; // s; 0 = at every snapshot
  double temperature = 298.15;      // K
};

struct MembraneConfig {
  std::string name;
  std::string shape;   // sphere | ellipsoid | plane | mesh
  std::string mesher;  // sphere: marching_tetrahedra | icosphere
  Vec3 center = Vec3::Zero();
  Vec3 radii = Vec3::Zero();           // sphere: all equal
  std::array<double, 2> size{0, 0};    // plane
  std::filesystem::path file;          // mesh
  double mesh_size = 0.0;              // nm
  MembraneMechanics mechanics;
  bool remesh = false;
  double min_size = 0.0, max_size = 0.0;  // nm
};

struct Config {
  std::string source;                // file name for messages
  std::string effective_toml;        // the table after --set overrides (stored in checkpoints)
  SimulationConfig simulation;
  MinimizerSettings mechanics;
  std::vector<MembraneConfig> membranes;
};

// Reads a config file, applies "key.path=value" overrides, validates everything.
// Throws InputError naming file, line and key on any problem.
Config loadConfig(const std::filesystem::path& file, const std::vector<std::string>& overrides);
// The same from TOML text (checkpoints store the effective config this way);
// relative mesh paths resolve against base_dir.
Config parseConfig(const std::string& toml_text, const std::string& source,
                   const std::filesystem::path& base_dir, const std::vector<std::string>& overrides);

}  // namespace cortex
