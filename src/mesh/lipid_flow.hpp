// Copies carried by the lipid's tangential flow while a deformation (a relaxation step on
// a fixed connectivity) changes the cells' areas.
//
// A fluid bilayer does not stretch locally: where a deformation makes a cell grow, lipid
// flows in from its neighbours, and the proteins on the lipid flow with it. The flow
// taken is the potential one (v = grad psi, the least dissipative for a friction-limited
// bilayer): on the mesh, edge fluxes F_ij = w_ij (psi_i - psi_j) with the cotangent
// weights (clipped at kMinWeight so the graph stays connected) and L psi = -g, where
// g_i = A'_i/D - A_i is the lipid cell i must gain (D = sum A'/sum A, the uniform dilation
// of the whole membrane, which moves no lipid). Copies move upwind: in each of K sub-steps
// a copy of cell i crosses to j with probability (F_ij / K) / (A_i + g_i k/K), K chosen so
// no cell sends more than what it holds per sub-step (fewer sub-steps smear less). A
// density uniform per unit area stays uniform in expectation (diluted by D), and totals
// are exact. A sharp edge (a coat) smears by the upwind scheme's numerical diffusion
// (docs/proteins.md measures it).
#pragma once

#include <span>
#include <vector>

#include "core/random.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex {

struct LipidFlowStats {
  int substeps = 0;
  double largest_outflow = 0.0;  // of a cell's area, over the whole step
};

LipidFlowStats carryWithLipidFlow(const SurfaceMesh& mesh, std::span<const double> area_before,
                                  std::span<const double> area_after, std::vector<std::vector<int>*> counts,
                                  RandomStream& random);

}  // namespace cortex
