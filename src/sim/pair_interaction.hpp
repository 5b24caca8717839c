// The mean-field pair attraction of membrane proteins (thesis 3.2.1 and 3.3.2, eqs.
// 3.4–3.5): a copy at vertex j feels R_j = μ₀ n_j + μ₂ (Δn)_j from the density n of the
// other copies, with μ₀ = ∫ μ dA and μ₂ = ¼ ∫ μ r² dA for a pair potential μ(r). For the
// Gaussian μ(r) = −h e^{−r²/σ²}: μ₀ = −π h σ², μ₂ = −π h σ⁴ / 4.
//
// Discretized on the dual cells with the cotangent Laplacian of the hops
// ((Δn)_j = Σ_k a_jk (n_k − n_j) / |C_j|, a_jk = (cot α + cot β)/2 = |C_j| / l²_jk) and
// n_j = N_j / |C_j|, R = K N with the symmetric kernel
//   K_jj = μ₀ / |C_j| − μ₂ Σ_k a_jk / |C_j|²,   K_jk = μ₂ a_jk / (|C_j| |C_k|),
// i.e. R is the gradient of W = ½ Nᵀ K N: hops biased by differences of R (less the
// moving copy's own field) keep detailed balance with e^{−W} (ChemistryEngine::
// SurfaceInteraction).
#pragma once

#include <vector>

#include "chem/chemistry_engine.hpp"
#include "chem/subvolume_graph.hpp"

namespace cortex {

struct PairMoments {
  double mu0 = 0.0;  // k_BT nm²
  double mu2 = 0.0;  // k_BT nm⁴
};

// μ₀ and μ₂ of μ(r) = −height e^{−r²/range²} (height in k_BT, range σ in nm).
PairMoments gaussianPairMoments(double height, double range);

// K on `graph` (a surface's dual cells): K_jj per subvolume, K_jk per directed edge. A
// species' own attraction and the cross attraction of two species are both this kernel.
struct PairKernel {
  std::vector<double> self, pair;
};
PairKernel pairKernel(const SubvolumeGraph& graph, const PairMoments& moments);

// The interaction on `graph` with external potential `potential` (k_BT per subvolume).
ChemistryEngine::SurfaceInteraction pairInteraction(const SubvolumeGraph& graph, const PairMoments& moments,
                                                    std::vector<double> potential, DriftScheme scheme);

}  // namespace cortex
