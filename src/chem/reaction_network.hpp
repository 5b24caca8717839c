// A ChemistryModel compiled into the flat arrays both engines loop over: per reaction the
// form of its propensity, its region and its net copy changes, and the dependency graph
// (which propensities an event invalidates, Gibson & Bruck 2000), including the 3D
// species a surface reaction reads in the compartment holding its subvolume.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "chem/chemistry_model.hpp"

namespace cortex {

// Propensity of a reaction in one subvolume = rate factor * constant * h(n).
struct ReactionKernel {
  enum class Kind : std::uint8_t { kConstant, kLinear, kPair, kDimer };
  Kind kind = Kind::kConstant;
  Index a = 0, b = 0;                   // reactant species (b only for kPair)
  bool a_held = false, b_held = false;  // read in the holder (a 3D species of a surface reaction)
};

// h(n): the number of distinct reactant combinations (header convention: n(n-1) for 2 A).
// `n` are the subvolume's copies, `held` those of the compartment holding it (the same
// array for a 3D subvolume).
inline double combinations(const ReactionKernel& r, const int* n, const int* held) {
  switch (r.kind) {
    case ReactionKernel::Kind::kConstant:
      return 1.0;
    case ReactionKernel::Kind::kLinear:
      return (r.a_held ? held : n)[r.a];
    case ReactionKernel::Kind::kPair:
      return static_cast<double>((r.a_held ? held : n)[r.a]) * (r.b_held ? held : n)[r.b];
    case ReactionKernel::Kind::kDimer: {
      const int m = (r.a_held ? held : n)[r.a];
      return static_cast<double>(m) * (m - 1);
    }
  }
  return 0.0;
}

// Compressed rows: row i is values[start[i] .. start[i+1]).
template <class T>
struct Rows {
  std::vector<Index> start{0};
  std::vector<T> values;
  std::span<const T> operator[](Index i) const {
    return {values.data() + start[i], static_cast<std::size_t>(start[i + 1] - start[i])};
  }
  void endRow() { start.push_back(static_cast<Index>(values.size())); }
};

struct SpeciesChange {
  Index species;
  int delta;
  bool held;  // a 3D species changed in the holder of the surface subvolume that fired
};

struct ReactionNetwork {
  // Validates the model (subvolumes, diffusion constants, reaction species, orders and
  // regions) and throws InputError naming the offending entry.
  explicit ReactionNetwork(const ChemistryModel& model);

  // Propensity constant of reaction r in a subvolume of `size` (nm^3 or nm^2) whose holder
  // has volume `holder_volume` (nm^3; unused for 3D reactions).
  double constant(Index r, double size, double holder_volume) const;

  Index numSpecies = 0;
  Index numReactions = 0;
  std::vector<ReactionKernel> kernels;
  std::vector<Index> region;        // per reaction: where it fires (0: 3D, k: surface k - 1)
  std::vector<Index> speciesRegion; // per species
  std::vector<int> order;           // per reaction: reactant copies
  std::vector<Index> sideSpecies;   // per reaction: first reactant (else first product), -1 if none
  std::vector<char> perSite;        // per reaction (ReactionDef::per_site)
  Rows<SpeciesChange> changes;      // per reaction: net changes, species with delta 0 omitted
  // Per reaction: a surface reaction whose reactants are all 3D species of the holder
  // (binding, "C -> M"). Its propensity in surface subvolume j is c_j h(n_holder), so the
  // engines carry it on the holder as one channel c_h = Σ_j c_j over the subvolumes it
  // holds, and draw j ∝ c_j when it fires: a 3D event then updates one propensity, not
  // one per vertex of the compartment.
  std::vector<char> aggregated;
  Rows<Index> affected;             // per reaction: reactions of the same subvolume its local changes touch
  // Per species: reactions reading it in their own subvolume; for a 3D species also the
  // aggregated surface reactions reading it (carried by the same subvolume).
  Rows<Index> dependents;
  Rows<Index> heldReaders;          // per 3D species: the other surface reactions reading it in their holder

 private:
  std::vector<double> rate_;                   // per reaction, as given
  std::vector<int> surface_order_, held_order_;  // per surface reaction: reactant copies of each kind
};

}  // namespace cortex
