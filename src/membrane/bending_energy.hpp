// Helfrich bending energy (thesis eq. 2.7): E = 2 kappa sum_v (H_v - H0)^2 A_v over
// interior vertices, with H_v from the signed or unsigned estimator (curvature.hpp).
// Where a protein coat covers a fraction phi_v = min(n_v a / A_v, 1) of a vertex's area
// (Membrane::coat, thesis eqs. 3.18-3.19), kappa and H0 there become
// kappa(phi) = ((1 - phi)/kappa + phi/(kappa + kappa_p))^-1 and H0 + H_c phi; phi follows
// A_v, so the area derivative carries it too.
#pragma once

#include "membrane/membrane_term.hpp"

namespace cortex {

class BendingEnergy final : public MembraneTerm {
 public:
  BendingEnergy(Membrane& m, BendingParameters p) : MembraneTerm(m, "bending"), p_(std::move(p)) { setTime(0.0); }
  double evaluate(const Evaluation& e) override;
  void setTime(double t) override {
    kappa_ = p_.modulus.at(t);
    h0_ = p_.spontaneous_curvature.at(t);
  }
  double modulus() const { return kappa_; }  // κ now, pN·nm

 private:
  BendingParameters p_;
  double kappa_ = 0.0, h0_ = 0.0;
  // Per vertex: dE/dA_v, and alpha, beta of dH_v/dx scaled by dE/dH_v.
  std::vector<double> area_coefficient_;
  std::vector<Vec3> alpha_, beta_;
  std::vector<Vec3> corner_gradient_;
};

}  // namespace cortex
