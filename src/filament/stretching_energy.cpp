#include "filament/stretching_energy.hpp"

namespace cortex {

// dE/dx1 = -dE/dx0 = k_s (l - l0) u, u the unit axis. A zero-length cylinder has no
// axis; its gradient is left out rather than made NaN.
double FilamentStretchingEnergy::evaluate(const Evaluation& e) {
  const double* x = e.x + 3 * static_cast<std::size_t>(layout_.bead_offset);
  double* g = e.gradient ? e.gradient + 3 * static_cast<std::size_t>(layout_.bead_offset) : nullptr;
  double energy = 0.0;
  for (const Cylinder& c : layout_.cylinders) {
    const double k = types_[c.type].stretching_stiffness;
    const Vec3 axis = Eigen::Map<const Vec3>(x + 3 * c.bead1) - Eigen::Map<const Vec3>(x + 3 * c.bead0);
    const double length = axis.norm();
    const double stretch = length - c.rest_length;
    energy += 0.5 * k * stretch * stretch;
    if (g && length > 0.0) {
      const Vec3 f = (k * stretch / length) * axis;
      Eigen::Map<Vec3>(g + 3 * c.bead1) += f;
      Eigen::Map<Vec3>(g + 3 * c.bead0) -= f;
    }
  }
  return energy;
}

}  // namespace cortex
