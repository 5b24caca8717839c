// A ChemistryModel compiled into the flat arrays both engines loop over: per reaction the
// form of its propensity and its net copy changes, the dependency graph (which
// propensities an event invalidates, Gibson & Bruck 2000), and per species the hop rate.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "chem/chemistry_model.hpp"

namespace cortex {

// Propensity of a reaction in one compartment = rate factor * constant * h(n).
struct ReactionKernel {
  enum class Kind : std::uint8_t { kConstant, kLinear, kPair, kDimer };
  Kind kind = Kind::kConstant;
  Index a = 0, b = 0;     // reactant species (b only for kPair)
  double constant = 0.0;  // stochastic rate constant c_r in one compartment's volume
};

// h(n): the number of distinct reactant combinations (header convention: n(n-1) for 2 A).
inline double combinations(const ReactionKernel& r, const int* n) {
  switch (r.kind) {
    case ReactionKernel::Kind::kConstant:
      return 1.0;
    case ReactionKernel::Kind::kLinear:
      return n[r.a];
    case ReactionKernel::Kind::kPair:
      return static_cast<double>(n[r.a]) * n[r.b];
    case ReactionKernel::Kind::kDimer:
      return static_cast<double>(n[r.a]) * (n[r.a] - 1);
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
};

struct ReactionNetwork {
  // Validates the model (grid, diffusion constants, reaction species and orders) and
  // throws InputError naming the offending entry.
  explicit ReactionNetwork(const ChemistryModel& model);

  Index numSpecies = 0;
  Index numReactions = 0;
  Index numCompartments = 0;
  std::vector<ReactionKernel> kernels;
  Rows<SpeciesChange> changes;   // per reaction: net changes, species with delta 0 omitted
  Rows<Index> affected;          // per reaction: reactions whose propensity it changes
  Rows<Index> dependents;        // per species: reactions whose propensity reads it
  std::vector<char> hooked;      // per reaction: carried out by a ReactionHook
  std::vector<char> perSite;     // per reaction: propensity per site (ReactionDef::per_site)
  std::vector<double> hopRate;   // per species: D/h^2, per copy and per face
  std::vector<Index> diffusing;  // species with hopRate > 0, ascending
};

}  // namespace cortex
