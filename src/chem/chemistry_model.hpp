// What the chemistry engine simulates: subvolumes (a graph), species living on them, and
// mass-action reactions, all in cortex units (nm, s, µM).
//
// Regions: region 0 is the 3D space (`volumes`, e.g. a compartment grid); region k >= 1 is
// the surface of membrane surfaces[k-1], whose subvolumes (the dual cells of its vertices)
// are handed to the engine at run time and replaced whenever the mesh is remeshed
// (ChemistryEngine::setSurface). A species lives in one region. A reaction fires in the
// region of its surface species if it has any (all on one surface), else in the 3D space;
// its 3D species are then those of the compartment that holds the surface subvolume.
#pragma once

#include <string>
#include <vector>

#include "chem/compartment_grid.hpp"
#include "chem/subvolume_graph.hpp"
#include "core/types.hpp"

namespace cortex {

struct SpeciesDef {
  std::string name;
  double diffusion = 0.0;  // nm^2/s
  Index surface = -1;      // -1: a 3D species; k: lives on ChemistryModel::surfaces[k]
  // Surface species only: the area one copy covers (nm^2). The copies of all species with
  // a footprint share a subvolume's area A: Σ n_s footprint_s ≤ crowdingRoom(A) (one
  // species alone: at most floor(A / footprint) copies; the crowding cap n <= n0 of thesis
  // 3.2.1). Hops into a full one and reactions that would overfill it are void events.
  // 0: no cap, and no area taken.
  double footprint = 0.0;
};

// The area copies may cover in a subvolume of area A: A with 1e-12 of slack, so that
// exactly floor(A / a) copies of footprint a fit whatever the rounding of n·a. The
// engine's cap and the initial placement (sim/surface_species.hpp) both use it.
inline double crowdingRoom(double area) { return area * (1.0 + 1e-12); }

// The side of a closed membrane a species is confined to (thesis 2.2.4.2); an empty
// membrane name means unconfined. Kept apart from SpeciesDef: the engine only sees the
// fractions it is given (ChemistryEngine::setConfinement), sim/ computes them.
struct SpeciesSide {
  std::string membrane;
  bool outside = false;
  bool operator==(const SpeciesSide&) const = default;
};

struct Stoichiometry {
  Index species;
  int count;
};

// Mass action. A 3D reaction's deterministic rate is k * prod [X]^nu (µM/s), with k in
// µM/s (order 0), 1/s (order 1) or 1/(µM s) (order 2). A surface reaction (thesis eq.
// 3.13) has propensity k A prod [M] prod [C] on a subvolume of area A, [M] in copies/nm^2
// for its surface species and [C] in copies/nm^3 for 3D species of the compartment that
// holds it; k in nm^(2 m + 3 c - 2)/s for m surface and c 3D reactant copies.
struct ReactionDef {
  std::string equation;
  std::vector<Stoichiometry> reactants, products;
  double rate = 0.0;
  // Its propensity counts sites (filament ends, site pairs), each reacting at k prod [X]:
  // under confinement it scales by f^-order (ChemistryEngine::setConfinement).
  bool per_site = false;
  int order() const;
};

// Reactions [begin, end) of a model and the one who owns them: registers their hook and
// alone sets their rate factors (ChemistryEngine::claimRateFactors).
struct ReactionRange {
  std::string owner;
  Index begin = 0, end = 0;
  bool contains(Index r) const { return r >= begin && r < end; }
  Index size() const { return end - begin; }
};

struct ChemistryModel {
  SubvolumeGraph volumes = gridGraph(CompartmentGrid{});  // region 0 (default: one 500 nm compartment)
  std::vector<std::string> surfaces;  // regions 1.., by membrane name
  std::vector<SpeciesDef> species;
  std::vector<ReactionDef> reactions;
  std::vector<ReactionRange> ranges;  // disjoint, in reaction order; every reaction in one

  // Appends reactions owned by `owner`; returns their range.
  ReactionRange addReactions(const std::string& owner, std::vector<ReactionDef> defs);
};

// Parses "A + B -> C", "2 A -> B", "-> A", "A ->", "A + A -> B" (= "2 A -> B") against
// the species names. Throws InputError with a message naming the problem (the caller
// adds file and key). Orders above 2 are refused.
ReactionDef parseReaction(const std::string& equation, double rate, const std::vector<SpeciesDef>& species);

// Propensity constant of a 3D reaction of `order` in a subvolume of volume V (nm^3) given copy
// numbers n: order 0: k·N·V; order 1: k·n; A + B: k/(N·V)·n_A·n_B; 2 A: k/(N·V)·n(n−1)
// (N = 602.214 copies per µM fL, V in fL), so that the mean event rate per volume is
// k·prod [X]^nu in the large-copy limit.
double stochasticRateConstant(double rate, int order, double volume_nm3);

}  // namespace cortex
