// Curvature generation (thesis 3.2.5, eqs. 3.18–3.19): lipid covered by proteins over an
// area fraction φ bends with the energy density
//   e(φ) = 2 κ(φ) (H − H_l − H_c φ)²,  κ(φ) = ((1 − φ)/κ_l + φ/(κ_l + κ_p))⁻¹,
//   H_c = H_p κ_p / (κ_l + κ_p),
// κ_l and H_l the lipid's own. The membrane's bending energy uses it under a coat
// (bending_energy.hpp) and curvature-sensing proteins feel its derivative
// (sim/curvature_sensing.hpp): one formula for both directions of the coupling.
#pragma once

#include <algorithm>

#include "core/types.hpp"

namespace cortex {

// A membrane species whose copies coat the lipid: at a vertex with n copies over its
// area A_v, φ = min(n a / A_v, 1), and the bending energy there is e(φ) A_v.
struct ProteinCoat {
  Index species = 0;                   // index into Membrane::speciesCopies()
  double area = 0.0;                   // nm^2 per copy, a
  double bending_modulus = 0.0;        // pN nm, κ_p
  double spontaneous_curvature = 0.0;  // 1/nm, H_p
};

// The area fraction n copies of area a cover on a cell of area A: φ = min(n a / A, 1) (a
// cell cannot be more than covered).
inline double coveredFraction(double copies, double copy_area, double cell_area) {
  return std::min(copies * copy_area / cell_area, 1.0);
}

struct CoatedLipid {
  double kappa;       // κ(φ), pN nm
  double offset;      // H − H_l − H_c φ, 1/nm
  double density;     // e(φ), pN/nm
  double derivative;  // de/dφ, pN/nm
};

// `curvature_offset` H − H_l; φ in [0, 1]. Inline: called per coated vertex in the
// bending loop.
inline CoatedLipid coatedLipid(double kappa_lipid, double kappa_protein, double protein_curvature,
                               double curvature_offset, double phi) {
  const double kappa_both = kappa_lipid + kappa_protein;
  const double kappa = 1.0 / ((1.0 - phi) / kappa_lipid + phi / kappa_both);
  const double hc = protein_curvature * kappa_protein / kappa_both;
  const double d = curvature_offset - hc * phi;
  // κ' = κ² (1/κ_l − 1/(κ_l + κ_p)), so e' = 2 κ' d² − 4 κ d H_c.
  return {kappa, d, 2.0 * kappa * d * d,
          2.0 * kappa * kappa * (1.0 / kappa_lipid - 1.0 / kappa_both) * d * d - 4.0 * kappa * d * hc};
}

}  // namespace cortex
