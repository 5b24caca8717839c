#include "filament/branch_energy.hpp"

namespace cortex {

// Position: dE/dx_d0 = k_p r with r = x_d0 - p, and -(1-w) k_p r, -w k_p r on the mother's
// beads. Angle: with m = mother axis, d = daughter axis and c = m.d/(|m||d|),
// dE/dm = 2K (c - c0) (d/(|m||d|) - c m/|m|^2), and likewise for d.
double BranchEnergy::evaluate(const Evaluation& e) {
  const double* x = e.x + 3 * static_cast<std::size_t>(layout_.bead_offset);
  double* g = e.gradient ? e.gradient + 3 * static_cast<std::size_t>(layout_.bead_offset) : nullptr;
  auto bead = [x](Index b) { return Eigen::Map<const Vec3>(x + 3 * b); };
  auto add = [g](Index b, const Vec3& v) { Eigen::Map<Vec3>(g + 3 * b) += v; };
  double energy = 0.0;
  for (const BranchJoint& j : layout_.branches) {
    const CylinderPoint& mp = j.mother;
    const Vec3 site = (1.0 - mp.w) * bead(mp.bead0) + mp.w * bead(mp.bead1);
    const Vec3 r = bead(j.daughter0) - site;
    energy += 0.5 * j.position_stiffness * r.squaredNorm();
    if (g) {
      const Vec3 f = j.position_stiffness * r;
      add(j.daughter0, f);
      add(mp.bead0, -(1.0 - mp.w) * f);
      add(mp.bead1, -mp.w * f);
    }

    const Vec3 m = bead(mp.bead1) - bead(mp.bead0), d = bead(j.daughter1) - bead(j.daughter0);
    const double lm = m.norm(), ld = d.norm();
    if (lm == 0.0 || ld == 0.0) continue;
    const double inv = 1.0 / (lm * ld);
    const double c = m.dot(d) * inv;
    const double dc = c - j.cos_angle;
    energy += j.angle_stiffness * dc * dc;
    if (g) {
      const double s = 2.0 * j.angle_stiffness * dc;
      const Vec3 gm = s * (inv * d - (c / (lm * lm)) * m);
      const Vec3 gd = s * (inv * m - (c / (ld * ld)) * d);
      add(mp.bead1, gm);
      add(mp.bead0, -gm);
      add(j.daughter1, gd);
      add(j.daughter0, -gd);
    }
  }
  return energy;
}

}  // namespace cortex
