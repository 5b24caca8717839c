// The other cylinders' excluded-volume push on a filament end between relaxations
// (end_load_probe.hpp): the pairs of excluded_volume_energy.hpp that hold the end's
// cylinder, evaluated with the network as it now stands. Within a window beads move only
// where an end grows or shrinks, so this is the term's exact force on the end bead: an
// end growing into the side of another filament stalls before it passes through it.
//
// Candidates come from one bounding box per filament, taken at update() and taken again
// for a filament whose ends have changed since (its lattice ends are its stamp), so a
// query costs one box test per filament plus the cylinders of the boxes it reaches.
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
  struct Box {
    Vec3 lo, hi;
    std::array<std::int64_t, 2> ends;  // the lattice ends it was taken at
  };
  const Box& boxOf(Index filament) const;
  // Are cylinder ca of filament a and cb of filament b a daughter's first cylinder and the
  // mother cylinder it starts on (no pair: the branch joint holds them)?
  bool branchPair(Index a, Index ca, Index b, Index cb) const;

  const FilamentNetwork& network_;
  double max_distance_ = 0.0;  // largest pair distance d0 of the types, nm
  mutable std::vector<Box> boxes_;
};

}  // namespace cortex
