#include "mesh/copy_carrier.hpp"

#include <algorithm>
#include <random>
#include <string_view>

#include "core/hash.hpp"

namespace cortex {
namespace {

// Area changes below this fraction of a cell are round-off of the edit's geometry (a
// flip or split evaluated in a different order), not lipid moving.
constexpr double kNegligibleChange = 1e-12;

template <class T>
std::uint64_t hashArray(const std::vector<T>& values, std::uint64_t hash) {
  return fnv1a64({reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)}, hash);
}

}  // namespace

std::vector<FaceArea> facesAround(const SurfaceMesh& m, Index v) {
  std::vector<FaceArea> faces;
  const auto& p = m.positions();
  for (const Index h : m.outgoingHalfedges(v)) {
    if (m.isBoundaryHalfedge(h)) continue;
    const Tri t{v, m.tip(h), m.tip(m.next(h))};
    faces.push_back({t, triangleArea(p[t[0]], p[t[1]], p[t[2]])});
  }
  return faces;
}

bool anyCopies(const std::vector<std::vector<int>*>& counts) {
  return std::any_of(counts.begin(), counts.end(), [](const std::vector<int>* c) {
    return std::any_of(c->begin(), c->end(), [](int n) { return n != 0; });
  });
}

CopyCarrier::CopyCarrier(std::vector<std::vector<int>*> counts, RandomStream random)
    : counts_(std::move(counts)), random_(random), active_(anyCopies(counts_)) {}

RandomStream streamKeyedByState(const SurfaceMesh& mesh, const std::vector<std::vector<int>*>& counts) {
  std::uint64_t key = hashArray(mesh.positions(), fnv1a64(""));
  for (const std::vector<int>* c : counts) key = hashArray(*c, key);
  return RandomStream(key, StreamId::kCopyTransport);
}

CopyCarrier CopyCarrier::keyedByState(const SurfaceMesh& mesh, std::vector<std::vector<int>*> counts) {
  RandomStream random = streamKeyedByState(mesh, counts);
  CopyCarrier carrier(std::move(counts), random);
  if (carrier.active()) carrier.measure(mesh);
  return carrier;
}

void CopyCarrier::measure(const SurfaceMesh& m) {
  if (active_) cell_area_ = dualCellAreas(m);
}

void CopyCarrier::addVertex() {
  if (active_) cell_area_.push_back(0.0);
}

void CopyCarrier::replaced(std::span<const FaceArea> removed, std::span<const FaceArea> added) {
  if (!active_) return;
  std::vector<Cell>& cells = cells_;  // reused: an edit touches a handful of cells
  cells.clear();
  auto cell = [&](Index v) -> Cell& {
    for (Cell& c : cells)
      if (c.vertex == v) return c;
    return cells.emplace_back(Cell{v, cell_area_[v], cell_area_[v]});
  };
  for (const FaceArea& f : removed)
    for (const Index v : f.vertices) cell(v).after -= f.area / 3.0;
  for (const FaceArea& f : added)
    for (const Index v : f.vertices) cell(v).after += f.area / 3.0;
  double growth = 0.0, loss = 0.0;
  for (Cell& c : cells) {
    // A cell reduced to round-off of what it was has vanished (a collapsed vertex).
    if (c.after <= kNegligibleChange * c.before) c.after = 0.0;
    cell_area_[c.vertex] = c.after;
    const double change = c.after - c.before, negligible = kNegligibleChange * c.before;
    if (change > negligible) growth += change;
    if (-change > negligible) loss += -change;
  }
  // Receivers and their weights: the cells that grew, by their gain. Where none grew (a
  // collapse of slivers of no area), the copies of a vanished cell go to the cells left,
  // by their area, and no other copy moves.
  std::vector<std::pair<Index, double>>& receivers = receivers_;  // vertex, weight
  receivers.clear();
  for (const Cell& c : cells) {
    const double weight = growth > 0.0 ? c.after - c.before : c.after;
    if (weight > kNegligibleChange * c.before && c.after > 0.0) receivers.emplace_back(c.vertex, weight);
  }
  if (receivers.empty()) return;
  double total_weight = 0.0;
  for (const auto& [v, w] : receivers) total_weight += w;
  // Where the edit lost area overall (a collapse on a curved surface), the shrinking
  // cells give only as much as the growing ones gained; a cell that vanished gives all.
  const double give = growth > 0.0 ? std::min(1.0, growth / loss) : 0.0;

  for (std::vector<int>* copies : counts_) {
    int leaving = 0;
    for (const Cell& c : cells) {
      int& n = (*copies)[c.vertex];
      const double shrink = c.before - c.after;
      if (n == 0 || !(shrink > kNegligibleChange * c.before)) continue;
      const int k = c.after == 0.0 ? n : std::binomial_distribution<int>(n, give * shrink / c.before)(random_);
      n -= k;
      leaving += k;
    }
    // Multinomial over the receivers, as a chain of binomials; the last takes the rest.
    double weight_left = total_weight;
    for (std::size_t r = 0; r < receivers.size() && leaving > 0; ++r) {
      const auto [v, weight] = receivers[r];
      const int k = r + 1 == receivers.size()
                        ? leaving
                        : std::binomial_distribution<int>(leaving, std::min(1.0, weight / weight_left))(random_);
      (*copies)[v] += k;
      leaving -= k;
      weight_left -= weight;
    }
  }
}

}  // namespace cortex
