#include "mesh/lipid_flow.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <utility>

#include "mesh/cotan.hpp"

namespace cortex {
namespace {

// Smallest edge weight (of the cotangent formula's 1/2 (cot a + cot b)): an edge of a
// non-Delaunay pair still carries some flow, and the Laplacian stays positive definite.
constexpr double kMinWeight = 0.05;
// Outflows below this share of a cell's lipid are round-off.
constexpr double kNoFlow = 1e-9;

// Lipid crossing one edge over the step (area), towards `to`.
struct Flux {
  Index to;
  double area;
};

// A parcel of lipid with the copies on it, and when it reached its present cell (the
// step's pseudo-time in [0, 1): the flow is steady over the step; -1 for the cell's own).
struct Parcel {
  double area;
  double time;
  std::vector<int> copies;  // per species
};

// Arrivals beyond this many per cell are merged pairwise (neighbours in arrival time):
// what a long chain of cells passes on stays ordered to within 1/kMostParcels of the step.
constexpr std::size_t kMostParcels = 32;

// Keeps the cells just sent to within kMostParcels arrivals.
void mergeParcels(std::vector<std::vector<Parcel>>& arrivals, const std::vector<Flux>& sent_to) {
  for (const Flux& e : sent_to) {
    std::vector<Parcel>& q = arrivals[e.to];
    if (q.size() <= kMostParcels) continue;
    std::stable_sort(q.begin(), q.end(), [](const Parcel& x, const Parcel& y) { return x.time < y.time; });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < q.size(); i += 2, ++kept) {
      Parcel merged = std::move(q[i]);
      if (i + 1 < q.size()) {
        merged.area += q[i + 1].area;
        for (std::size_t s = 0; s < merged.copies.size(); ++s) merged.copies[s] += q[i + 1].copies[s];
      }
      q[kept] = std::move(merged);
    }
    q.resize(kept);
  }
}

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

  // The edges' fluxes (area per whole step), each from its upstream end.
  std::vector<std::vector<Flux>> out_edges(n);
  std::vector<double> outflow(n, 0.0);
  for (const auto& [h, w] : edges) {
    const Index a = m.tail(h), b = m.tip(h);
    const double f = w * (psi[a] - psi[b]);
    if (f > 0) out_edges[a].push_back({b, f}), outflow[a] += f;
    if (f < 0) out_edges[b].push_back({a, -f}), outflow[b] += -f;
  }
  double worst = 0.0;
  for (Index v = 0; v < n; ++v) {
    const double smallest = std::min(before[v], before[v] + growth[v]);
    if (outflow[v] > 0) worst = std::max(worst, smallest > 0 ? outflow[v] / smallest : INFINITY);
  }
  stats.largest_outflow = worst;
  // Below kNoFlow the flow is round-off of a uniform dilation; a cell of no area cannot
  // hold lipid to send (a degenerate mesh: the relaxation's checks report it).
  if (!(worst > kNoFlow) || !std::isfinite(worst)) return stats;

  // Upstream cells first: psi falls along every flux, so each cell's arrivals are all
  // known when its turn comes (ties in psi carry no flux between them).
  std::vector<Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Index x, Index y) { return psi[x] > psi[y]; });
  const std::size_t species = counts.size();
  std::vector<std::vector<Parcel>> arrivals(n);
  std::vector<Parcel> leaving;
  std::vector<int> stay(species);
  for (const Index v : order) {
    std::vector<Parcel>& queue = arrivals[v];
    if (outflow[v] <= 0.0) {
      for (const Parcel& p : queue)
        for (std::size_t s = 0; s < species; ++s) (*counts[s])[v] += p.copies[s];
      continue;
    }
    ++stats.cells_drained;
    // The cell's lipid in the order it leaves: its own first, then what arrives, in the
    // order it arrives (plug flow through the cell).
    std::stable_sort(queue.begin(), queue.end(), [](const Parcel& x, const Parcel& y) { return x.time < y.time; });
    Parcel own{before[v], -1.0, std::vector<int>(species)};
    for (std::size_t s = 0; s < species; ++s) own.copies[s] = std::exchange((*counts[s])[v], 0);
    queue.insert(queue.begin(), std::move(own));
    std::fill(stay.begin(), stay.end(), 0);
    leaving.clear();
    double sent = 0.0;
    for (Parcel& p : queue) {
      const double share = p.area > 0 ? std::clamp((outflow[v] - sent) / p.area, 0.0, 1.0) : 1.0;
      Parcel out{share * p.area, sent / outflow[v], std::vector<int>(species)};
      for (std::size_t s = 0; s < species; ++s) {
        out.copies[s] = share >= 1.0 ? p.copies[s]
                        : share <= 0.0 ? 0
                                       : std::binomial_distribution<int>(p.copies[s], share)(random);
        stay[s] += p.copies[s] - out.copies[s];
      }
      sent += out.area;
      if (out.area > 0.0 || std::any_of(out.copies.begin(), out.copies.end(), [](int c) { return c > 0; }))
        leaving.push_back(std::move(out));
    }
    for (std::size_t s = 0; s < species; ++s) (*counts[s])[v] += stay[s];
    std::vector<Parcel>().swap(queue);
    // Each parcel leaves over the edges in proportion to their fluxes (the last edge takes
    // what is left, so round-off in the shares cannot lose a copy).
    const std::vector<Flux>& edges_out = out_edges[v];
    for (const Parcel& p : leaving) {
      double rest = outflow[v];
      std::vector<int> left = p.copies;
      for (const Flux& e : edges_out) {
        const double q = &e == &edges_out.back() ? 1.0 : std::min(1.0, e.area / rest);
        Parcel part{p.area * e.area / outflow[v], p.time, std::vector<int>(species)};
        for (std::size_t s = 0; s < species; ++s) {
          part.copies[s] = q >= 1.0 ? left[s] : std::binomial_distribution<int>(left[s], q)(random);
          left[s] -= part.copies[s];
        }
        rest -= e.area;
        arrivals[e.to].push_back(std::move(part));
      }
    }
    mergeParcels(arrivals, edges_out);
  }
  return stats;
}

}  // namespace cortex
