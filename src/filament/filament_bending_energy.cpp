#include "filament/filament_bending_energy.hpp"

namespace cortex {

// With c = cos theta: dc/dt1 = t2/(|t1||t2|) - c t1/|t1|^2 and symmetrically for t2;
// t1 depends on x1 - x0 and t2 on x2 - x1, so dE/dx0 = K dc/dt1, dE/dx2 = -K dc/dt2 and
// dE/dx1 = -(dE/dx0 + dE/dx2). Degenerate (zero-length) hinges contribute nothing.
double FilamentBendingEnergy::evaluate(const Evaluation& e) {
  const double* x = e.x + 3 * static_cast<std::size_t>(layout_.bead_offset);
  double* g = e.gradient ? e.gradient + 3 * static_cast<std::size_t>(layout_.bead_offset) : nullptr;
  double energy = 0.0;
  for (const Hinge& h : layout_.hinges) {
    const Eigen::Map<const Vec3> x0(x + 3 * h.bead0), x1(x + 3 * h.bead1), x2(x + 3 * h.bead2);
    const Vec3 t1 = x1 - x0, t2 = x2 - x1;
    const double l1 = t1.norm(), l2 = t2.norm();
    if (l1 == 0.0 || l2 == 0.0) continue;
    const double k = types_[h.type].bending_stiffness;
    const double inv = 1.0 / (l1 * l2);
    const double c = t1.dot(t2) * inv;
    energy += k * (1.0 - c);
    if (g) {
      const Vec3 g0 = k * (inv * t2 - (c / (l1 * l1)) * t1);
      const Vec3 g2 = -k * (inv * t1 - (c / (l2 * l2)) * t2);
      Eigen::Map<Vec3>(g + 3 * h.bead0) += g0;
      Eigen::Map<Vec3>(g + 3 * h.bead2) += g2;
      Eigen::Map<Vec3>(g + 3 * h.bead1) -= g0 + g2;
    }
  }
  return energy;
}

}  // namespace cortex
