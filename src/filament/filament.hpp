// One bead-cylinder filament (MEDYAN's model; Popov, Komianos & Papoian 2016): beads
// joined by straight cylinders, each cylinder holding a whole number of monomers.
//
// Monomers are numbered along the filament by a lattice coordinate fixed to the
// filament (minus end to plus end, increasing towards the plus end; it may be negative
// after minus-end growth). Bead i sits at lattice[i]; cylinder i spans monomers
// [lattice[i], lattice[i+1]). Inner beads keep their coordinate for life, so binding
// sites (fixed lattice coordinates) stay put as the ends grow and shrink: growth moves
// the end bead out by one monomer size until its cylinder is full, then adds a bead.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace cortex {

struct Filament {
  Index type = 0;
  std::vector<Vec3> beads;                 // nm, minus end first
  std::vector<std::int64_t> lattice;       // monomer coordinate of each bead
  bool minus_capped = false;               // held by a branch: the minus end neither grows nor shrinks
  bool minus_anchored = false;             // minus-end bead fixed in space (and its end inert)
  // Anchored and clamped: the first cylinder's other bead is fixed too, so the anchor
  // holds the filament's direction (a clamped end) instead of letting it pivot (a pinned
  // one). With a single cylinder that bead is the plus end: the filament is then rigid.
  bool minus_clamped = false;
  bool minusEndActive() const { return !minus_capped && !minus_anchored; }

  std::int64_t minusEnd() const { return lattice.front(); }
  std::int64_t plusEnd() const { return lattice.back(); }
  std::int64_t monomers() const { return lattice.back() - lattice.front(); }
  Index numCylinders() const { return static_cast<Index>(beads.size()) - 1; }
  // Does lattice coordinate s (monomers) lie on the filament?
  bool covers(double s) const { return s >= static_cast<double>(minusEnd()) && s <= static_cast<double>(plusEnd()); }
  // Cylinder holding s (clamped to the filament) and the weight of its plus-side bead.
  std::pair<Index, double> locate(double s) const;
  Vec3 pointAt(double s) const;
  // Unit vector from the minus-side to the plus-side bead of the end cylinders.
  Vec3 plusDirection() const;
  Vec3 minusDirection() const;  // pointing outwards from the minus end (growth direction)
  double length() const;        // nm, sum of the cylinder lengths
};

// A straight filament of `monomers` monomers from `minus_end` along unit `direction`,
// cut into cylinders of `cylinder_monomers` from the minus end, the last one partial.
Filament makeStraightFilament(Index type, const Vec3& minus_end, const Vec3& direction, std::int64_t monomers,
                              int cylinder_monomers, double monomer_size);

}  // namespace cortex
