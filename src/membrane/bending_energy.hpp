// Helfrich bending energy (thesis eq. 2.7): E = 2 kappa sum_v (H_v - H0)^2 A_v over
// interior vertices, with H_v from the signed or unsigned estimator (curvature.hpp).
#pragma once

#include "membrane/membrane_term.hpp"

namespace cortex {

class BendingEnergy final : public MembraneTerm {
 public:
  explicit BendingEnergy(Membrane& m) : MembraneTerm(m, "bending") {}
  double evaluate(const Evaluation& e) override;

 private:
  // Per vertex: dE/dA_v, and alpha, beta of dH_v/dx scaled by dE/dH_v.
  std::vector<double> area_coefficient_;
  std::vector<Vec3> alpha_, beta_;
  std::vector<Vec3> corner_gradient_;
};

}  // namespace cortex
