// Curvature sensing of membrane proteins (thesis 3.2.5, eqs. 3.17–3.19): with e(φ) the
// bending energy density of lipid whose area fraction φ proteins cover
// (membrane/protein_coat.hpp; H₀ below is its H_c), the energy of one protein in the
// dual cell of area |C| around a vertex of mean curvature H that holds n other copies:
// its chemical potential
//   V_H = A_p ∂e/∂φ at φ = n A_p / |C|,
// the form the thesis gives for crowded cells. In the dilute limit it is the closed form
// 2 A_p κ_eff (H² − 2 H H_p), κ_eff = κ_l κ_p / (κ_l + κ_p), on any mesh. The thesis'
// difference form |C| [e(φ + A_p/|C|) − e(φ)] adds to it a self-energy
// ≈ A_p² e''(0) / (2|C|) ≈ 2 κ_l H₀² A_p² / |C| that depends on the mesh (a protein
// spread over its cell interacting with itself; docs/proteins.md). φ is capped at 1 (a
// cell fully covered).
#pragma once

#include "sim/run_config.hpp"

namespace cortex {

// pN nm. `kappa_lipid` κ_l (pN nm, > 0), `lipid_curvature` H_l (1/nm), `mean_curvature`
// H (1/nm), `copies` n other copies in the cell, `cell_area` |C| (nm^2, > 0).
double curvatureSensingEnergy(const CurvatureSensingConfig& protein, double kappa_lipid, double lipid_curvature,
                              double mean_curvature, double copies, double cell_area);

}  // namespace cortex
