#include "filament/walls.hpp"

namespace cortex {

Walls wallsOf(const FilamentConfig& config, const Vec3& box_min, const Vec3& box_max, double margin) {
  Walls w;
  w.margin = margin;
  if (config.boundary && config.boundary->shape == BoundaryConfig::Shape::kSphere) {
    w.sphere = true;
    w.center = config.boundary->center;
    w.radius = config.boundary->radius - margin;
    w.min = w.center - Vec3::Constant(w.radius);
    w.max = w.center + Vec3::Constant(w.radius);
  } else {
    w.min = (config.boundary ? config.boundary->min : box_min) + Vec3::Constant(margin);
    w.max = (config.boundary ? config.boundary->max : box_max) - Vec3::Constant(margin);
  }
  return w;
}

}  // namespace cortex
