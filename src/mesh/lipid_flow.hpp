// Copies carried by the lipid's tangential flow while a deformation (a relaxation step on
// a fixed connectivity) changes the cells' areas.
//
// A fluid bilayer does not stretch locally: where a deformation makes a cell grow, lipid
// flows in from its neighbours, and the proteins on the lipid flow with it. The flow
// taken is the potential one (v = grad psi, the least dissipative for a friction-limited
// bilayer): on the mesh, edge fluxes F_ij = w_ij (psi_i - psi_j) with the cotangent
// weights (clipped at kMinWeight so the graph stays connected) and L psi = -g, where
// g_i = A'_i/D - A_i is the lipid cell i must gain (D = sum A'/sum A, the uniform dilation
// of the whole membrane, which moves no lipid). The flow is taken as steady over the step
// and the lipid as passing through each cell in order (plug flow): cells are visited
// upstream first (psi falls along every flux); a cell sends out F_i = sum_j F_ij of lipid,
// its own first, then what arrived, in the order it arrived, and each parcel sent leaves
// over the edges in proportion to their fluxes; a parcel's copies are split binomially
// by area wherever only part of it moves on. A density uniform per unit area stays
// uniform in expectation (diluted by D), and totals are exact. Unlike upwind sub-steps,
// which mix each cell's arrivals with what it holds at every sub-step (numerical
// diffusion over the whole path), a coat carried across tens of cells keeps its edge to
// within the mixing where outflows merge (docs/proteins.md measures both).
#pragma once

#include <span>
#include <vector>

#include "core/random.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex {

struct LipidFlowStats {
  Index cells_drained = 0;       // cells lipid left (0: nothing flowed)
  double largest_outflow = 0.0;  // of a cell's area, over the whole step
};

LipidFlowStats carryWithLipidFlow(const SurfaceMesh& mesh, std::span<const double> area_before,
                                  std::span<const double> area_after, std::vector<std::vector<int>*> counts,
                                  RandomStream& random);

}  // namespace cortex
