#include "mesh/lipid_flow.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "mesh/cotan.hpp"

namespace cortex {
namespace {

// Smallest edge weight (of the cotangent formula's 1/2 (cot a + cot b)): an edge of a
// non-Delaunay pair still carries some flow, and the Laplacian stays positive definite.
constexpr double kMinWeight = 0.05;
// Outflows below this share of a cell's lipid are round-off.
constexpr double kNoFlow = 1e-9;
// Largest share of a cell's copies that may leave it in one sub-step: the upwind
// transport smears an edge less the closer each sub-step comes to emptying the cells
// it drains (a coat's coverage after a transport across ~9 cells: 0.456 at 1.0, 0.446 at
// 0.5, against 0.515 before it).
constexpr double kMaxShare = 1.0;

}  // namespace

LipidFlowStats carryWithLipidFlow(const SurfaceMesh& m, std::span<const double> before, std::span<const double> after,
                                  std::vector<std::vector<int>*> counts, RandomStream& random) {
  LipidFlowStats stats;
  const Index n = m.numVertices();
  const double total_before = std::accumulate(before.begin(), before.end(), 0.0);
  const double total_after = std::accumulate(after.begin(), after.end(), 0.0);
  if (n < 2 || !(total_before > 0.0) || !(total_after > 0.0)) return stats;
  // Lipid each cell must gain (in the areas before the step): what it holds after, with
  // the whole membrane's uniform dilation divided out, less what it held. Sums to zero.
  const double dilation = total_after / total_before;
  Eigen::VectorXd growth(n);
  double largest_growth = 0.0;
  for (Index v = 0; v < n; ++v) {
    growth[v] = after[v] / dilation - before[v];
    if (before[v] > 0) largest_growth = std::max(largest_growth, std::abs(growth[v]) / before[v]);
  }
  // No cell's share of lipid changed beyond round-off (a relaxation that found the shape
  // at rest): nothing flows, and the solve is skipped.
  if (!(largest_growth > kNoFlow)) return stats;

  const std::vector<double> cot = cotanWeights(m);
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<std::pair<Index, double>> edges;  // half-edge h < twin, weight
  for (Index h = 0; h < m.numHalfedges(); ++h) {
    const Index t = m.twin(h);
    if (h > t) continue;
    const double w = std::max(cot[h], kMinWeight);
    const Index a = m.tail(h), b = m.tip(h);
    entries.emplace_back(a, a, w), entries.emplace_back(b, b, w);
    entries.emplace_back(a, b, -w), entries.emplace_back(b, a, -w);
    edges.emplace_back(h, w);
  }
  // The Laplacian is singular (constants); with the sum of the growth zero, adding to one
  // diagonal entry pins psi_0 = 0 and leaves every other equation exact.
  entries.emplace_back(0, 0, 1.0);
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  if (solver.info() != Eigen::Success) return stats;
  const Eigen::VectorXd psi = solver.solve(-growth);

  // Outgoing fluxes per cell (area per whole step), and the sub-steps they need.
  struct Flux {
    Index from, to;
    double area;
  };
  std::vector<Flux> fluxes;
  std::vector<double> outflow(n, 0.0);
  for (const auto& [h, w] : edges) {
    const Index a = m.tail(h), b = m.tip(h);
    const double f = w * (psi[a] - psi[b]);
    if (f > 0) fluxes.push_back({a, b, f}), outflow[a] += f;
    if (f < 0) fluxes.push_back({b, a, -f}), outflow[b] += -f;
  }
  std::stable_sort(fluxes.begin(), fluxes.end(), [](const Flux& x, const Flux& y) { return x.from < y.from; });
  double worst = 0.0;
  for (Index v = 0; v < n; ++v) {
    const double smallest = std::min(before[v], before[v] + growth[v]);
    if (outflow[v] > 0) worst = std::max(worst, smallest > 0 ? outflow[v] / smallest : INFINITY);
  }
  stats.largest_outflow = worst;
  // Below kNoFlow the flow is round-off of a uniform dilation; a cell of no area cannot
  // hold lipid to send (a degenerate mesh: the relaxation's checks report it).
  if (!(worst > kNoFlow) || !std::isfinite(worst)) return stats;
  stats.substeps = static_cast<int>(std::ceil(worst / kMaxShare));

  std::vector<int> arriving(n);
  for (int k = 0; k < stats.substeps; ++k) {
    const double s = static_cast<double>(k) / stats.substeps;
    for (std::vector<int>* copies : counts) {
      std::fill(arriving.begin(), arriving.end(), 0);
      for (std::size_t i = 0; i < fluxes.size();) {
        const Index v = fluxes[i].from;
        const double area = before[v] + s * growth[v];  // the lipid the cell holds now
        int left = (*copies)[v];
        double stay = 1.0;  // probability, among the copies not yet sent, of staying
        for (; i < fluxes.size() && fluxes[i].from == v; ++i) {
          const double p = fluxes[i].area / stats.substeps / area;
          if (left == 0) continue;
          const int go = std::binomial_distribution<int>(left, std::min(1.0, p / stay))(random);
          left -= go, stay -= p;
          (*copies)[v] -= go, arriving[fluxes[i].to] += go;
        }
      }
      for (Index v = 0; v < n; ++v) (*copies)[v] += arriving[v];
    }
  }
  return stats;
}

}  // namespace cortex
