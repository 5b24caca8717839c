#include "sim/curvature_sensing.hpp"

#include <algorithm>

namespace cortex {

double curvatureSensingEnergy(const CurvatureSensingConfig& p, double kappa_lipid, double lipid_curvature, double H,
                              double copies, double cell_area) {
  const double phi = std::min(copies * p.area / cell_area, 1.0);
  const double kappa_both = kappa_lipid + p.bending_modulus;
  // κ(φ): lipid and protein-covered lipid in series; κ' = κ² (1/κ_l − 1/(κ_l + κ_p)).
  const double kappa = 1.0 / ((1.0 - phi) / kappa_lipid + phi / kappa_both);
  const double dkappa = kappa * kappa * (1.0 / kappa_lipid - 1.0 / kappa_both);
  const double h0 = p.spontaneous_curvature * p.bending_modulus / kappa_both;
  const double d = H - lipid_curvature - h0 * phi;
  return p.area * (2.0 * dkappa * d * d - 4.0 * kappa * d * h0);  // A_p de/dφ
}

}  // namespace cortex
