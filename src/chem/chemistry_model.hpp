// What the chemistry engine simulates: a grid of cubic compartments, diffusing species,
// and mass-action reactions, all in cortex units (nm, s, µM).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace cortex {

// Avogadro's number in cortex units: copies per µM per fL (1 fL = 1 µm³ = 1e9 nm³).
inline constexpr double kCopiesPerMicromolarFemtoliter = 602.214076;
// Copies that make 1 µM in a volume of `volume_nm3` (N_A V).
inline double copiesPerMicromolar(double volume_nm3) { return kCopiesPerMicromolarFemtoliter * volume_nm3 * 1e-9; }

struct CompartmentGrid {
  double size = 500.0;               // nm, cube edge
  std::array<int, 3> shape{1, 1, 1}; // compartments per axis; the box is shape*size from the origin
  Index count() const { return shape[0] * shape[1] * shape[2]; }
  Index index(int i, int j, int k) const { return (k * shape[1] + j) * shape[0] + i; }
  std::array<int, 3> coords(Index c) const { return {c % shape[0], (c / shape[0]) % shape[1], c / (shape[0] * shape[1])}; }
  double volume() const { return size * size * size; }  // nm^3
  Vec3 extent() const { return size * Vec3(shape[0], shape[1], shape[2]); }  // nm, the box's far corner
  double copiesPerMicromolar() const { return cortex::copiesPerMicromolar(volume()); }  // in one compartment
  // Face neighbours of c (up to 6; walls are reflective, so missing ones are absent).
  int neighbours(Index c, std::array<Index, 6>& out) const;
  Vec3 centre(Index c) const {
    const auto ijk = coords(c);
    return Vec3((ijk[0] + 0.5) * size, (ijk[1] + 0.5) * size, (ijk[2] + 0.5) * size);
  }
  // Compartment holding point x (nm), clamped to the box.
  Index locate(const Vec3& x) const;
};

struct SpeciesDef {
  std::string name;
  double diffusion = 0.0;  // nm^2/s
};

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

// Mass action: the deterministic rate of the reaction is k * prod [X]^nu (µM/s), with k
// in µM/s (order 0), 1/s (order 1) or 1/(µM s) (order 2).
struct ReactionDef {
  std::string equation;
  std::vector<Stoichiometry> reactants, products;
  double rate = 0.0;
  // Carried out by the engine's ReactionHook (filament reactions); such reactions are
  // built by the program, never parsed from a config.
  bool hooked = false;
  // Its propensity counts sites (filament ends, site pairs), each reacting at k prod [X]:
  // under confinement it scales by f^-order (ChemistryEngine::setConfinement).
  bool per_site = false;
  int order() const;
};

// Parses "A + B -> C", "2 A -> B", "-> A", "A ->", "A + A -> B" (= "2 A -> B") against
// the species names. Throws InputError with a message naming the problem (the caller
// adds file and key). Orders above 2 are refused.
ReactionDef parseReaction(const std::string& equation, double rate, const std::vector<SpeciesDef>& species);

// Propensity of one reaction channel in a compartment of volume V (nm^3) given copy
// numbers n: order 0: k·N·V; order 1: k·n; A + B: k/(N·V)·n_A·n_B; 2 A: k/(N·V)·n(n−1)
// (N = 602.214 copies per µM fL, V in fL), so that the mean event rate per volume is
// k·prod [X]^nu in the large-copy limit.
double stochasticRateConstant(const ReactionDef& reaction, double volume_nm3);

struct ChemistryModel {
  CompartmentGrid grid;
  std::vector<SpeciesDef> species;
  std::vector<ReactionDef> reactions;
};

}  // namespace cortex
