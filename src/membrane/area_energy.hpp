// Area elasticity (thesis eqs. 2.3, 2.4) and surface tension (eq. 2.5).
#pragma once

#include "membrane/membrane_term.hpp"

namespace cortex {

// E = k_area / (2 A0) (A - A0)^2 over the whole membrane (eq. 2.4).
class GlobalAreaEnergy final : public MembraneTerm {
 public:
  explicit GlobalAreaEnergy(Membrane& m) : MembraneTerm(m, "area") {}
  double evaluate(const Evaluation& e) override;
};

// E = sum_v k_area / (2 A0_v) (A_v - A0_v)^2, vertices as material points (eq. 2.3).
class PerVertexAreaEnergy final : public MembraneTerm {
 public:
  explicit PerVertexAreaEnergy(Membrane& m) : MembraneTerm(m, "area") {}
  double evaluate(const Evaluation& e) override;

 private:
  std::vector<double> coefficient_;  // per vertex, dE/dA_v
  std::vector<Vec3> corner_gradient_;
};

// E = gamma A (eq. 2.5): a lipid reservoir at fixed chemical potential.
class TensionEnergy final : public MembraneTerm {
 public:
  explicit TensionEnergy(Membrane& m) : MembraneTerm(m, "tension") {}
  double evaluate(const Evaluation& e) override;
};

}  // namespace cortex
