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
#include "chem/hop_drift.hpp"
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

// An axis-aligned box (nm): a reaction with a region fires only in the compartments
// whose centres lie inside it; a surface species with a region starts on the vertices
// inside it.
struct BoxRegion {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  bool contains(const Vec3& x) const { return (x.array() >= min.array()).all() && (x.array() <= max.array()).all(); }
};

// An external potential acting on a membrane species (thesis 3.2.1: V in h = R + V), in
// units of k_BT. A Gaussian stripe across `axis`: V = height · exp(−(x_axis − center)² /
// (2 width²)); a ramp: V = slope · (x_axis − center).
struct SurfacePotentialConfig {
  enum class Kind { kGaussianStripe, kRamp } kind = Kind::kGaussianStripe;
  int axis = 0;           // 0, 1, 2 = x, y, z
  double center = 0.0;    // nm
  double width = 1.0;     // nm (stripe: standard deviation)
  double height = 0.0;    // k_BT (stripe)
  double slope = 0.0;     // k_BT/nm (ramp)
};

// Curvature sensing of a membrane species (thesis 3.2.5, eqs. 3.17–3.19): a protein of
// area A_p, bending rigidity κ_p and spontaneous curvature H_p; the lipid's κ_l is the
// membrane's bending modulus (docs/proteins.md).
struct CurvatureSensingConfig {
  double area = 0.0;                   // nm^2, A_p
  double bending_modulus = 0.0;        // pN nm, κ_p
  double spontaneous_curvature = 0.0;  // 1/nm, H_p
  // The copies also change the membrane's bending energy where they are (curvature
  // generation, Membrane::coat): the two-way coupling. At most one species per membrane.
  bool generates = false;
};

// The pair attraction of a membrane species' copies (thesis 3.3.2): a Gaussian pair
// potential μ(r) = −height · e^{−r²/range²} in its mean-field form R = μ₀ n + μ₂ Δn
// (sim/pair_interaction.hpp). Positive heights attract, negative ones repel.
struct SurfaceInteractionConfig {
  double height = 0.0;  // k_BT
  double range = 0.0;   // nm, σ
};

// [[membrane.species.cross_interaction]]: the same attraction between the copies of this
// species and those of `species`, another species of the membrane; declared on one of
// the two.
struct CrossInteractionConfig {
  std::string species;
  SurfaceInteractionConfig interaction;
};

// A protein species living on a membrane's vertices (thesis chapter 3), from
// [[membrane.species]]: copies per vertex, hopping along the mesh's edges
// (docs/proteins.md).
struct SurfaceSpeciesConfig {
  std::string name;
  double diffusion = 0.0;  // nm^2/s
  // The initial copies, spread over the vertices (of `region`, if given) in proportion to
  // their dual-cell areas: `copies`, or `density` (copies/µm^2) times that area, resolved
  // when the mesh is built.
  std::int64_t copies = 0;
  std::optional<double> density;
  std::optional<BoxRegion> region;
  // nm^2 one copy covers: a vertex holds at most floor(|C_j| / footprint) copies (the
  // crowding cap, SpeciesDef::footprint); 0: no cap.
  double footprint = 0.0;
  std::optional<SurfacePotentialConfig> potential;
  std::optional<CurvatureSensingConfig> curvature;
  std::optional<SurfaceInteractionConfig> interaction;
  std::vector<CrossInteractionConfig> cross;
  DriftScheme drift = DriftScheme::kExponential;
};

// Whether the energy of a copy of species `index` (of one membrane's `species`) depends on
// the copies: a pair attraction of its own or across species (declared on either side),
// or curvature sensing. The chemistry engine then keeps its rates exact event by event
// (ChemistryEngine::SurfaceInteraction), and its copies unbind one at a time.
inline bool copyDependentEnergy(const std::vector<SurfaceSpeciesConfig>& species, std::size_t index) {
  const SurfaceSpeciesConfig& s = species[index];
  if (s.interaction || s.curvature || !s.cross.empty()) return true;
  for (const SurfaceSpeciesConfig& other : species)
    for (const CrossInteractionConfig& c : other.cross)
      if (c.species == s.name) return true;
  return false;
}

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
  // area_model was given (not defaulted): a loaded mesh's default depends on whether it
  // turns out closed (sim/membrane_builder.cpp).
  bool area_model_given = false;
  bool remesh = false;
  double min_size = 0.0, max_size = 0.0;  // nm
  double remesh_tolerance = 0.0;          // nm, largest mesh-to-surface distance (sizing)
  std::vector<SurfaceSpeciesConfig> species;
};

// Where a reaction may fire: in a box, and/or on one side of a membrane (for reactions
// of unconfined species; confined species carry their side themselves).
struct ReactionRestriction {
  std::optional<BoxRegion> region;
  SpeciesSide side;
  bool restricted() const { return region.has_value() || !side.membrane.empty(); }
};

// The chemistry of the config: its grid, 3D and surface species and reactions (rates in
// config units), and how each 3D species starts (surface species start from their
// membrane's SurfaceSpeciesConfig). Modules append their own reactions when the
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
  // Membranes with [[membrane.species]], by name: the model's surfaces. Their species
  // follow the 3D ones in `species` (SpeciesDef::surface set, no initial copies in 3D).
  std::vector<std::string> surfaces;
};

struct Config {
  std::string source;                // file name for messages
  std::string effective_toml;        // the table after --set overrides (stored in checkpoints)
  SimulationConfig simulation;
  MinimizerSettings mechanics;
  std::vector<MembraneConfig> membranes;
  std::optional<ChemistryConfig> chemistry;  // present when [[species]] or [[membrane.species]] are given
  std::optional<FilamentConfig> filaments;   // present when [[filament_type]] are given
  // Excluded volume between every membrane and the filaments' beads: on whenever both
  // are present, unless [membrane_filament] enabled = false.
  std::optional<MembraneBeadExclusionParams> membrane_filament;
};

}  // namespace cortex
