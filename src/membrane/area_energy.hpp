// Area elasticity (thesis eqs. 2.3, 2.4) and surface tension (eq. 2.5).
#pragma once

#include "membrane/membrane_term.hpp"

namespace cortex {

// E = k_area / (2 A0) (A - A0)^2 over the whole membrane (eq. 2.4), A0 its target area.
class GlobalAreaEnergy final : public MembraneTerm {
 public:
  GlobalAreaEnergy(Membrane& m, AreaParameters p) : MembraneTerm(m, "area"), p_(std::move(p)) { setTime(0.0); }
  double evaluate(const Evaluation& e) override;
  void setTime(double t) override {
    k_ = p_.modulus.at(t);
    a0_ = membrane_.targetArea(t);
  }
  // d2E/dA2 = k / A0 (pN/nm^3): the stiffness of this penalty along the area gradient.
  double stiffness() const { return k_ / a0_; }

 private:
  AreaParameters p_;
  double k_ = 0.0, a0_ = 0.0;
};

// E = sum_v k_area / (2 A0_v) (A_v - A0_v)^2, vertices as material points (eq. 2.3); A0_v
// the initial vertex areas scaled by target area / initial area.
class PerVertexAreaEnergy final : public MembraneTerm {
 public:
  PerVertexAreaEnergy(Membrane& m, AreaParameters p) : MembraneTerm(m, "area"), p_(std::move(p)) { setTime(0.0); }
  double evaluate(const Evaluation& e) override;
  void setTime(double t) override {
    k_ = p_.modulus.at(t);
    scale_ = membrane_.targetArea(t) / membrane_.material().initial_area;
  }

 private:
  AreaParameters p_;
  double k_ = 0.0, scale_ = 1.0;
  std::vector<double> coefficient_;  // per vertex, dE/dA_v
  std::vector<Vec3> corner_gradient_;
};

// E = gamma A (eq. 2.5): a lipid reservoir at fixed chemical potential.
class TensionEnergy final : public MembraneTerm {
 public:
  TensionEnergy(Membrane& m, TensionParameters p) : MembraneTerm(m, "tension"), p_(std::move(p)) { setTime(0.0); }
  double evaluate(const Evaluation& e) override;
  void setTime(double t) override { gamma_ = p_.tension.at(t); }

 private:
  TensionParameters p_;
  double gamma_ = 0.0;
};

}  // namespace cortex
