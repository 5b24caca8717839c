// Mesh regularization: keeps triangles near-equilateral while the shape relaxes.
//
//   E = k_reg sum_t [ (l_a^2 + l_b^2 + l_c^2) / (4 sqrt 3) - A_t ]
//
// Each bracket is >= 0 and vanishes exactly for an equilateral triangle, whatever its
// size, so the term resists shearing triangles into slivers without favouring any
// area. A fluid membrane has no in-plane shear stiffness: vertex motion within the
// surface is a discretization artefact, and without a restoring force the discrete
// bending energy drifts vertices into degenerate triangles during long minimizations.
// (Mem3DG regularizes its meshes with similar in-plane terms: Zhu et al., Biophys.
// Rep. 2022.) Choose k_reg small against the physical moduli; docs/membrane.md.
#pragma once

#include "membrane/membrane_term.hpp"

namespace cortex {

class RegularizationEnergy final : public MembraneTerm {
 public:
  explicit RegularizationEnergy(Membrane& m) : MembraneTerm(m, "regularization") {}
  double evaluate(const Evaluation& e) override;

 private:
  std::vector<Vec3> corner_gradient_;
};

}  // namespace cortex
