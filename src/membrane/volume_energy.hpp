// Osmotic volume energy (thesis eqs. 2.10-2.12): E = k_volume / (2 V0) (V - V0)^2.
#pragma once

#include "membrane/membrane_term.hpp"

namespace cortex {

class VolumeEnergy final : public MembraneTerm {
 public:
  VolumeEnergy(Membrane& m, VolumeParameters p) : MembraneTerm(m, "volume"), p_(std::move(p)) { setTime(0.0); }
  double evaluate(const Evaluation& e) override {
    const MeshGeometry& g = membrane_.geometry(e);
    const double dv = g.volume - v0_;
    if (double* grad = gradientOf(e)) addScaledVertexField(grad, g.volume_gradient, k_ * dv / v0_);
    return 0.5 * k_ * dv * dv / v0_;
  }
  // V0: target_volume, else reduced_volume times the volume of the sphere of the target
  // area, else the initial volume.
  void setTime(double t) override {
    k_ = p_.modulus.at(t);
    if (p_.target_volume.isSet())
      v0_ = p_.target_volume.at(t);
    else if (p_.reduced_volume.isSet())
      v0_ = p_.reduced_volume.at(t) * sphereVolumeOfArea(membrane_.targetArea(t));
    else
      v0_ = membrane_.material().initial_volume;
  }

 private:
  VolumeParameters p_;
  double k_ = 0.0, v0_ = 0.0;
};

}  // namespace cortex
