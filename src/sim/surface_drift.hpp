// Surface diffusion in a potential (thesis 3.2.1–3.2.2, eqs. 3.6–3.11): the potential
// h_j (k_BT units) at every vertex and the factors that bias the free hop rates
// D (cot α + cot β)/(2|C_i|) along each edge, so that copies are stationary in
// proportion to |C_j| e^{−h_j}.
//
// Along a directed edge i → j with x = h_j − h_i the free rate is multiplied by the
// factor of chem/hop_drift.hpp (exponential B(x), or linear 1 − x/2 closed at |x| ≥ 2).
// Both lump the drift onto the edge (a two-point flux) rather than use eq. 3.9's full
// finite-element a_jk; they agree with it to first order in x on a smooth potential
// (docs/proteins.md).
#pragma once

#include <vector>

#include "chem/subvolume_graph.hpp"
#include "sim/run_config.hpp"

namespace cortex {

// The potential (k_BT) at a point.
double surfacePotential(const SurfacePotentialConfig& potential, const Vec3& x);

struct DriftFactors {
  std::vector<double> factors;  // per directed edge of the graph
  Index closed_edges = 0;       // linear scheme: edges closed because |x| > 2
};

// `h` per subvolume of `graph` (k_BT). Energies that depend on the copies (pair
// attraction, curvature sensing) are the engine's, event by event
// (ChemistryEngine::SurfaceInteraction).
DriftFactors driftFactors(const SubvolumeGraph& graph, const std::vector<double>& h, DriftScheme scheme);

}  // namespace cortex
