// Osmotic volume energy (thesis eqs. 2.10-2.12): E = k_volume / (2 V0) (V - V0)^2.
#pragma once

#include "membrane/membrane_term.hpp"

namespace cortex {

class VolumeEnergy final : public MembraneTerm {
 public:
  VolumeEnergy(Membrane& m, VolumeParameters p) : MembraneTerm(m, "volume"), p_(std::move(p)) { setTime(0.0); }
  // V0 = Membrane::targetVolume.
  double evaluate(const Evaluation& e) override {
    const MeshGeometry& g = membrane_.geometry(e);
    const double dv = g.volume - v0_;
    if (double* grad = gradientOf(e)) addScaledVertexField(grad, g.volume_gradient, k_ * dv / v0_);
    return 0.5 * k_ * dv * dv / v0_;
  }
  void setTime(double t) override {
    k_ = p_.modulus.at(t);
    v0_ = membrane_.targetVolume(t);
  }
  // d2E/dV2 = k / V0 (pN/nm^5): the stiffness of this penalty along the volume gradient.
  double stiffness() const { return k_ / v0_; }

 private:
  VolumeParameters p_;
  double k_ = 0.0, v0_ = 0.0;
};

}  // namespace cortex
