// Membrane confinement of 3D species (thesis 2.2.4.2): slices the membranes that confine
// species and hands each species the fractions of its side to the engine, and sets the
// rate factors of the config's reactions limited to a box or a side of a membrane. Recomputed from the membranes alone, so a checkpoint needs to
// store nothing for it.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/feedback.hpp"
#include "sim/run_config.hpp"

namespace cortex {

struct SideFractions {
  std::vector<double> volume;                // per compartment
  std::vector<std::array<double, 6>> faces;  // per compartment, in GridFace order
};

// Per side: the fractions of the grid on that side, or nothing for an empty side. Each
// membrane is sliced once. Throws InputError for a membrane that does not exist or is
// not closed (loaded meshes are only known to be closed once read).
std::vector<std::optional<SideFractions>> sideFractions(const std::vector<std::unique_ptr<Membrane>>& membranes,
                                                        const std::vector<SpeciesSide>& sides,
                                                        const CompartmentGrid& grid);

// Warns (once, when the System is built) of every membrane that confines a species or
// a reaction and is less than two compartments across its smallest extent: the planar
// cut then misses the volume inside by over 1%, 6% at 1.5 compartments and 10-20% at
// one (CompartmentSlicing tests, docs/chemistry.md). Under one compartment across
// (10-50%) it throws InputError instead.
void checkSlicingResolution(const std::vector<std::unique_ptr<Membrane>>& membranes, const ChemistryConfig& config);

// The surface (index in ChemistryConfig::surfaces) whose species reaction `def` joins
// with 3D species (binding, unbinding), or -1 if it has no membrane species or no 3D ones.
Index surfaceJoinedTo3D(const ReactionDef& def, const ChemistryConfig& config);
// The vertices of a membrane outside the compartment grid (beyond round-off of its
// faces), and the share of its area their dual cells carry.
struct OutsideGrid {
  Index vertices = 0;
  double area_fraction = 0.0;
};
OutsideGrid outsideGrid(const Membrane& membrane, const CompartmentGrid& grid);
// During a run a membrane may reach past the grid's walls by this share of its area
// (its dual cells beyond them) before the run stops; the start allows none. The error it
// makes is at most this: copies bound into the grid's edge from that area, and a
// membrane's inside beyond a wall, whose copies crowd into the rest, encloses less than
// this share of its volume for a cap (docs/chemistry.md).
inline constexpr double kLargestAreaOutsideGrid = 0.01;

// A membrane holding species or reactions on its inside (`inside = "NAME"`) must lie
// within the compartment grid: slicing sees only the grid, so the part of its inside
// beyond a wall would hold nothing and its species would crowd into the rest (a vesicle
// with 16% of its volume beyond a wall held its copies at concentrations 19% too high,
// exit 0). Returns what is wrong (the key that confines, the membrane, its vertices
// outside, the grid's box), or nothing.
// Outside sides need no such check: the grid is then the world the species live in.
// `sides` per species (of `species`, their definitions), `restrictions` per reaction;
// `tolerated` the share of its area a membrane may have outside (0 or
// kLargestAreaOutsideGrid).
std::optional<std::string> insideBeyondGrid(const std::vector<std::unique_ptr<Membrane>>& membranes,
                                            const CompartmentGrid& grid, const std::vector<SpeciesSide>& sides,
                                            const std::vector<ReactionRestriction>& restrictions,
                                            const std::vector<SpeciesDef>& species, double tolerated);

// A reaction of membrane species with 3D species needs its membrane within the
// compartment grid (each vertex reacts with the compartment holding it; clamped into the
// grid, one outside reacts with the grid's edge, while no volume beyond it holds
// species). And if its 3D species are confined to a side of another membrane, it fires
// only at the vertices on that side.
// Throws InputError (naming the reaction) when no vertex lies there: it could never fire, and a run
// would report zero events as if that were the rate's doing. Nested vesicles pass (the
// inner one's vertices are inside the outer one); a membrane's own sides always do.
void checkSurfaceReactionsCanFire(const std::vector<std::unique_ptr<Membrane>>& membranes, const ChemistryConfig& config,
                               const std::string& source);

class ConfinementFeedback final : public Feedback {
 public:
  // `config_factors`: the rate factors of the config's reactions, of which this writes
  // those of restricted (3D) reactions in the compartments; the surface species write
  // those of unbinding reactions on the vertices (sim/surface_species.hpp).
  ConfinementFeedback(const ChemistryConfig& config, ChemistryEngine& engine, RateFactors config_factors);
  // Re-slices and applies: after every relaxation (membranes move and are remeshed).
  void update(System& system) override;

 private:
  CompartmentGrid grid_;
  std::vector<SpeciesSide> sides_;                      // per species
  std::vector<ReactionRestriction> restrictions_;       // per config reaction
  ChemistryEngine& engine_;
  RateFactors factors_;
  bool active_;  // anything confined or restricted at all
};

}  // namespace cortex
