// Typed parameters of a run, as parsed and validated by io/config.cpp, or written in
// C++ by tests and benchmarks. They live in sim/ so that the simulation depends on
// parameters, never on the file format: a System is built from a Config alone.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "chem/chemistry_engine.hpp"
#include "core/types.hpp"
#include "filament/filament_params.hpp"
#include "interact/membrane_bead_exclusion.hpp"
#include "mech/minimizer.hpp"
#include "membrane/membrane.hpp"
#include "mesh/triangle_soup.hpp"

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
  std::filesystem::path file;          // mesh: an OBJ or PLY file,
  std::optional<TriangleSoup> soup;    // or the triangles themselves (programs and tests)
  double mesh_size = 0.0;              // nm
  MembraneMechanics mechanics;
  bool remesh = false;
  double min_size = 0.0, max_size = 0.0;  // nm
  double remesh_tolerance = 0.0;          // nm, largest mesh-to-surface distance (sizing)
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

// The 3D chemistry of the config: its grid, species and reactions (rates in config
// units), and how each species starts. Modules append their own reactions when the
// System is assembled.
struct ChemistryConfig {
  EngineKind engine = EngineKind::kNextSubvolume;
  double max_events_per_window = 1e9;  // ChemistryEngine::setEventLimit
  CompartmentGrid grid;
  std::vector<SpeciesDef> species;
  std::vector<ReactionDef> reactions;
  std::vector<std::int64_t> initial_copies;                // per species: in the whole box (or its side)
  std::vector<ReactionRestriction> reaction_restrictions;  // per reaction
  std::vector<SpeciesSide> sides;                          // per species
};

struct Config {
  std::string source;                // file name for messages
  std::string effective_toml;        // the table after --set overrides (stored in checkpoints)
  SimulationConfig simulation;
  MinimizerSettings mechanics;
  std::vector<MembraneConfig> membranes;
  std::optional<ChemistryConfig> chemistry;  // present when [[species]] are given
  std::optional<FilamentConfig> filaments;   // present when [[filament_type]] are given
  // Excluded volume between every membrane and the filaments' beads: on whenever both
  // are present, unless [membrane_filament] enabled = false.
  std::optional<MembraneBeadExclusionParams> membrane_filament;
};

}  // namespace cortex
