// The other cylinders' excluded-volume push on a filament end between relaxations
// (end_load_probe.hpp): the pairs of excluded_volume_energy.hpp that hold the end's
// cylinder, evaluated with the network as it now stands. Within a window beads move only
// where an end grows or shrinks, so this is the term's exact force on the end bead: an
// end growing into the side of another filament stalls before it passes through it.
//
// Candidates come from a grid of cells, each listing the filaments with a cylinder whose
// bounding box reaches it, built at update(). The grid only grows within a window: the
// probe learns which ends moved from the queries themselves (the chemistry asks after
// every event that moves an end) and registers the end's cylinder where it now is;
// filaments created since update() (nuclei, daughters) are checked whole at every query.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "filament/end_load_probe.hpp"
#include "filament/filament_network.hpp"

namespace cortex {

class CylinderExclusionEndLoads final : public EndLoadProbe {
 public:
  explicit CylinderExclusionEndLoads(const FilamentNetwork& network);
  void update() override;
  Vec3 forceAt(Index filament, const Vec3& point, bool plus_end) const override;

 private:
  using Cell = std::array<Index, 3>;
  Cell cellOf(const Vec3& p) const;
  // Lists `filament` in every cell the box [lo - reach, hi + reach] touches.
  void enlist(Index filament, const Vec3& lo, const Vec3& hi) const;
  void enlistCylinder(Index filament, Index cylinder) const;
  // Are cylinder ca of filament a and cb of filament b a daughter's first cylinder and the
  // mother cylinder it starts on (no pair: the branch joint holds them)?
  bool branchPair(Index a, Index ca, Index b, Index cb) const;

  const FilamentNetwork& network_;
  double max_distance_ = 0.0;  // largest pair distance d0 of the types, nm
  // The grid: cells of edge `cell_` from `origin_`, `dims_` per axis (positions beyond
  // it fall in the border cells), each listing filaments.
  Vec3 origin_ = Vec3::Zero();
  double cell_ = 1.0;
  Cell dims_{0, 0, 0};
  mutable std::vector<std::vector<Index>> cells_;
  // How many filaments the grid holds (those at update()) and each one's lattice ends
  // when its cylinders were last listed.
  Index gridded_ = 0;
  mutable std::vector<std::array<std::int64_t, 2>> ends_;
  // Per-query scratch: the query that last saw each filament.
  mutable std::vector<std::uint64_t> seen_;
  mutable std::uint64_t query_ = 0;
};

}  // namespace cortex
