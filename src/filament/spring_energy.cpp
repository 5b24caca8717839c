#include "filament/spring_energy.hpp"

namespace cortex {

Vec3 cylinderPoint(const CylinderPoint& p, const double* x, Index bead_offset) {
  const double* b = x + 3 * static_cast<std::size_t>(bead_offset);
  return (1.0 - p.w) * Eigen::Map<const Vec3>(b + 3 * p.bead0) + p.w * Eigen::Map<const Vec3>(b + 3 * p.bead1);
}

double springTension(const Spring& s, const double* x, Index bead_offset) {
  const double length = (cylinderPoint(s.b, x, bead_offset) - cylinderPoint(s.a, x, bead_offset)).norm();
  return s.stiffness * (length - s.rest_length);
}

std::vector<double> SpringEnergy::tensions(const double* x) const {
  std::vector<double> out;
  out.reserve(springs_.size());
  for (const Spring& s : springs_) out.push_back(springTension(s, x, layout_.bead_offset));
  return out;
}

// dE/dpb = -dE/dpa = k (L - l0) r/L with r = pb - pa, shared between each point's two
// beads by its weights. A zero-length spring has no direction: no gradient.
double SpringEnergy::evaluate(const Evaluation& e) {
  const Index offset = layout_.bead_offset;
  double* g = e.gradient ? e.gradient + 3 * static_cast<std::size_t>(offset) : nullptr;
  double energy = 0.0;
  for (const Spring& s : springs_) {
    const Vec3 r = cylinderPoint(s.b, e.x, offset) - cylinderPoint(s.a, e.x, offset);
    const double length = r.norm();
    const double stretch = length - s.rest_length;
    energy += 0.5 * s.stiffness * stretch * stretch;
    if (g && length > 0.0) {
      const Vec3 f = (s.stiffness * stretch / length) * r;
      Eigen::Map<Vec3>(g + 3 * s.b.bead0) += (1.0 - s.b.w) * f;
      Eigen::Map<Vec3>(g + 3 * s.b.bead1) += s.b.w * f;
      Eigen::Map<Vec3>(g + 3 * s.a.bead0) -= (1.0 - s.a.w) * f;
      Eigen::Map<Vec3>(g + 3 * s.a.bead1) -= s.a.w * f;
    }
  }
  return energy;
}

}  // namespace cortex
