#include "sim/curvature_sensing.hpp"

#include "membrane/protein_coat.hpp"

namespace cortex {

double curvatureSensingEnergy(const CurvatureSensingConfig& p, double kappa_lipid, double lipid_curvature, double H,
                              double copies, double cell_area) {
  const double phi = coveredFraction(copies, p.area, cell_area);
  return p.area *
         coatedLipid(kappa_lipid, p.bending_modulus, p.spontaneous_curvature, H - lipid_curvature, phi).derivative;
}

}  // namespace cortex
