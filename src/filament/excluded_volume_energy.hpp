// Steric repulsion between cylinders that share no bead: E = k/2 (d0 - d)^2 for d < d0,
// d the distance between the closest points of the two segments, k and d0 the means of
// the two types' excluded_volume_stiffness and excluded_volume_distance. A daughter's
// first cylinder and the mother cylinder it starts on are not a pair.
//
// Pairs come from a Verlet-style list built with a cell list over cylinder midpoints.
// A pair is listed when its segment distance at the build is below d0 + skin; since
// moving every bead by less than skin/2 moves every point of a segment by less than
// skin/2, such pair distances change by less than skin, so the list stays complete until
// some bead has moved skin/2. evaluate() rebuilds when that happens or the layout
// version changed, so the energy is exact at every call. Pairs are kept in (i, j) order,
// so energies and forces do not depend on where the list was built (a resumed run, or
// the ratchet's load read after a minimization, sums in the same order).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "filament/filament_layout.hpp"
#include "filament/filament_params.hpp"
#include "filament/filament_term.hpp"

namespace cortex {

// Closest points p0 + s (p1 - p0) and q0 + t (q1 - q0), s, t in [0, 1], of two segments.
// Parallel segments (and zero-length ones) get a deterministic choice among the minimizers.
struct SegmentClosestPoints {
  double s, t;
  Vec3 delta;  // closest point on p minus closest point on q
};
SegmentClosestPoints closestPoints(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

// The exclusion between cylinders of types a and b: the means of their stiffnesses and
// distances.
struct PairExclusion {
  double stiffness, distance;  // pN/nm, nm
};
PairExclusion pairExclusion(const FilamentType& a, const FilamentType& b);

// The push between segments p and q closer than the pair's distance d0: energy
// k/2 (d0 - d)^2 and the force on p's closest point (q's is its opposite), which the
// beads share with weights 1 - s, s (and 1 - t, t). None when d >= d0.
struct CylinderContact {
  double energy;  // pN nm
  Vec3 push;      // pN
  double s, t;
};
std::optional<CylinderContact> cylinderContact(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1,
                                               const PairExclusion& pair);

class CylinderExclusionEnergy final : public FilamentTerm {
 public:
  CylinderExclusionEnergy(const FilamentLayout& layout, const std::vector<FilamentType>& types,
                          double skin = 10.0);  // nm
  double evaluate(const Evaluation& e) override;
  bool isContact() const override { return true; }

  // Diagnostics, for tests and benchmarks.
  std::int64_t rebuilds() const { return rebuilds_; }
  std::size_t listedPairs() const { return pairs_.size(); }

 private:
  struct Pair {
    Index a, b;
    PairExclusion exclusion;
    double built;  // closest distance at the last build
  };
  // Fills moved_ with each bead's displacement since the last build and returns the
  // largest, or infinity when the layout changed.
  double displacements(const double* x);
  void rebuild(const double* x);

  const std::vector<FilamentType>& types_;
  double skin_;
  std::vector<Pair> pairs_;
  // State at the last build: layout version and bead positions.
  bool built_ = false;
  std::uint64_t built_version_ = 0;
  Index built_offset_ = 0;
  std::vector<double> built_x_;
  std::vector<double> moved_;  // per bead, nm
  std::int64_t rebuilds_ = 0;
  // Cell-list scratch, kept to avoid reallocating on every rebuild.
  std::vector<Vec3> midpoint_;
  std::vector<double> half_length_;
  std::vector<Index> cell_of_, cell_start_, cell_items_, cursor_;
  std::vector<std::uint64_t> excluded_;  // cylinder pairs (a < b) joined by a branch
};

}  // namespace cortex
