// Osmotic volume energy (thesis eqs. 2.10-2.12): E = k_volume / (2 V0) (V - V0)^2.
#pragma once

#include "membrane/membrane_term.hpp"

namespace cortex {

class VolumeEnergy final : public MembraneTerm {
 public:
  explicit VolumeEnergy(Membrane& m) : MembraneTerm(m, "volume") {}
  double evaluate(const Evaluation& e) override {
    const MeshGeometry& g = membrane_.geometry(e);
    const double k = membrane_.now().k_volume, v0 = membrane_.now().volume0;
    const double dv = g.volume - v0;
    if (double* grad = gradientOf(e)) addScaledVertexField(grad, g.volume_gradient, k * dv / v0);
    return 0.5 * k * dv * dv / v0;
  }
};

}  // namespace cortex
