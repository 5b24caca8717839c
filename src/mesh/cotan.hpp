// Cotangent weights of the discrete Laplace-Beltrami operator (Pinkall & Polthier 1993):
// w_ij = 1/2 (cot alpha_ij + cot beta_ij), alpha and beta the angles opposite edge ij
// (one term on a boundary edge). With them, dA/dx_i = sum_j w_ij (x_i - x_j).
#pragma once

#include <vector>

#include "mesh/surface_mesh.hpp"

namespace cortex {

// Cotangent of the angle opposite half-edge h in its triangle (0 for boundary half-edges).
double cotanOpposite(const SurfaceMesh& mesh, Index h);
// Per half-edge weight w (equal for h and its twin).
std::vector<double> cotanWeights(const SurfaceMesh& mesh);

}  // namespace cortex
