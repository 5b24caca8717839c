// Initial filaments from [[filaments]]: where each one starts, before any chemistry or
// mechanics. A pure function of (config, box, stream), so a run is reproducible.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "core/random.hpp"
#include "core/types.hpp"
#include "filament/filament_params.hpp"

namespace cortex {

struct FilamentSeed {
  Index type;        // FilamentType index
  Vec3 minus_end;    // nm
  Vec3 direction;    // unit vector from the minus end to the plus end
  int monomers;      // length / monomer_size, rounded, >= 1
  bool fixed_minus_end = false;
  bool clamped_minus_end = false;
};

// Where a [[filaments]] entry with `inside` may put filaments, given by the caller (the
// filament module knows no membranes): a box to draw minus ends from and the test of a
// whole straight filament, minus end to plus end.
struct PlacementRegion {
  Vec3 min, max;
  std::function<bool(const Vec3& minus_end, const Vec3& plus_end)> holds;
};

// Every bead of every filament lies inside the boundary (the [boundary] walls, or the
// box [box_min, box_max] without one), at least 2 screening lengths from the walls.
// random: minus ends uniform in the region (default: the boundary's bounding box, within
// the PlacementRegion's box where there is one), directions uniform on the sphere,
// rejection-sampled until the filament fits (and the PlacementRegion holds it).
// bundle: parallel filaments on a hexagonal lattice perpendicular to the axis.
// Throws InputError naming filaments.N when a filament does not fit.
// regions: one per config.initial entry (empty where it has no `inside`), or none at all.
std::vector<FilamentSeed> placeFilaments(const FilamentConfig& config, const Vec3& box_min, const Vec3& box_max,
                                         RandomStream& random,
                                         const std::vector<std::optional<PlacementRegion>>& regions = {});

// Margin (nm) kept between beads and walls: walls push within a few screening lengths.
double placementMargin(const FilamentConfig& config);

}  // namespace cortex
