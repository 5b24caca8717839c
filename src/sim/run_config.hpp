// Typed parameters of a run, as parsed and validated by io/config.cpp. They live in
// sim/ so that the simulation depends on parameters, never on the file format.
#pragma once

#include <array>
#include <optional>
#include <filesystem>
#include <string>
#include <vector>

#include "chem/chemistry_engine.hpp"
#include "core/types.hpp"
#include "filament/filament_params.hpp"
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
  double remesh_tolerance = 0.0;          // nm, largest mesh-to-surface distance (sizing)
};

// Initial amount of a 3D species: copies in the whole box (or, when confined, in the
// volume on its side of the membrane), spread uniformly at random in that volume.
struct SpeciesConfig {
  SpeciesDef def;
  std::int64_t copies = 0;
  SpeciesSide side;
};

// An axis-aligned box (nm): a reaction with a region fires only in the compartments
// whose centres lie inside it.
struct BoxRegion {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  bool contains(const Vec3& x) const { return (x.array() >= min.array()).all() && (x.array() <= max.array()).all(); }
};

// Where a reaction may fire: in a box, and/or on one side of a membrane (for reactions
// of unconfined species; confined species carry their side themselves).
struct ReactionRestriction {
  std::optional<BoxRegion> region;
  SpeciesSide side;
  bool restricted() const { return region.has_value() || !side.membrane.empty(); }
};

struct ChemistryConfig {
  EngineKind engine = EngineKind::kNextSubvolume;
  ChemistryModel model;                 // grid, species, reactions (rates in config units)
  std::vector<std::int64_t> initial_copies;  // per species, whole box
  std::vector<ReactionRestriction> reaction_restrictions;  // per reaction
  std::vector<SpeciesSide> sides;            // per species
};

struct Config {
  std::string source;                // file name for messages
  std::string effective_toml;        // the table after --set overrides (stored in checkpoints)
  SimulationConfig simulation;
  MinimizerSettings mechanics;
  std::vector<MembraneConfig> membranes;
  std::optional<ChemistryConfig> chemistry;  // present when [[species]] are given
  std::optional<FilamentConfig> filaments;   // present when [[filament_type]] are given
};

}  // namespace cortex
