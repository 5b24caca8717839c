// Initial filaments from [[filaments]]: where each one starts, before any chemistry or
// mechanics. A pure function of (config, box, stream), so a run is reproducible.
#pragma once

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

// Every bead of every filament lies inside the boundary (the [boundary] walls, or the
// box [box_min, box_max] without one), at least 2 screening lengths from the walls.
// random: minus ends uniform in the region (default: the boundary's bounding box),
// directions uniform on the sphere, rejection-sampled until the filament fits.
// bundle: parallel filaments on a hexagonal lattice perpendicular to the axis.
// Throws InputError naming filaments.N when a filament does not fit.
std::vector<FilamentSeed> placeFilaments(const FilamentConfig& config, const Vec3& box_min, const Vec3& box_max,
                                         RandomStream& random);

// Margin (nm) kept between beads and walls: walls push within a few screening lengths.
double placementMargin(const FilamentConfig& config);

}  // namespace cortex
