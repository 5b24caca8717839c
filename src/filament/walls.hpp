// The region filament beads must stay in: the [boundary] walls (box or sphere), or the
// compartment grid's box without them, optionally shrunk by a margin. Convex, so a
// straight filament lies inside whenever both its ends do.
#pragma once

#include "core/types.hpp"
#include "filament/filament_params.hpp"

namespace cortex {

struct Walls {
  bool sphere = false;
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();  // box, or the sphere's bounding box
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
  double margin = 0.0;

  bool contains(const Vec3& x) const {
    if (sphere) return (x - center).norm() <= radius;
    return (x.array() >= min.array()).all() && (x.array() <= max.array()).all();
  }
};

// config.boundary shrunk by `margin` (nm), or [box_min, box_max] shrunk by it.
Walls wallsOf(const FilamentConfig& config, const Vec3& box_min, const Vec3& box_max, double margin);

}  // namespace cortex
