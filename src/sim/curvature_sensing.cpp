#include "sim/curvature_sensing.hpp"

#include <algorithm>

#include "membrane/protein_coat.hpp"

namespace cortex {

double curvatureSensingEnergy(const CurvatureSensingConfig& p, double kappa_lipid, double lipid_curvature, double H,
                              double copies, double cell_area) {
  const double phi = std::min(copies * p.area / cell_area, 1.0);
  return p.area *
         coatedLipid(kappa_lipid, p.bending_modulus, p.spontaneous_curvature, H - lipid_curvature, phi).derivative;
}

}  // namespace cortex
