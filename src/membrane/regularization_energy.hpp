// Mesh regularization: keeps triangles well shaped and evenly sized while the shape
// relaxes, so that the discrete energies stay accurate.
//
//   E = k_reg sum_t [ (q_t - 1) + (A_t / Ā - 1)^2 ],
//   q_t = (l_a^2 + l_b^2 + l_c^2) / (4 sqrt(3) A_t),   Ā = A / (number of triangles)
//
// q_t >= 1 with equality exactly for an equilateral triangle, and grows without bound as
// a triangle flattens into a sliver; the second part vanishes on a mesh of equal
// triangle areas. Neither depends on the membrane's size. Why it is needed: a fluid
// membrane has no in-plane stiffness, so moving vertices within the surface costs no
// physical energy, but the discrete energies are not exactly invariant under it. Left
// alone, a minimizer collapses triangles (forces then become meaningless) or grows a few
// huge flat triangles whose under-resolved curvature lowers the discrete bending energy
// below the continuum bound 8 pi kappa. (Mem3DG regularizes its meshes with similar
// in-plane terms: Zhu et al., Biophys. Rep. 2022.) k_reg is an energy per triangle in
// pN nm; keep it a fraction of kBT (docs/membrane.md).
#pragma once

#include "membrane/membrane_term.hpp"

namespace cortex {

class RegularizationEnergy final : public MembraneTerm {
 public:
  RegularizationEnergy(Membrane& m, RegularizationParameters p)
      : MembraneTerm(m, "regularization"), p_(std::move(p)) {
    setTime(0.0);
  }
  double evaluate(const Evaluation& e) override;
  void setTime(double t) override { k_ = p_.strength.at(t); }

 private:
  RegularizationParameters p_;
  double k_ = 0.0;
  std::vector<Vec3> corner_gradient_;
};

}  // namespace cortex
