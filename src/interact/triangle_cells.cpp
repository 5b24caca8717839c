#include "interact/triangle_cells.hpp"

namespace cortex {

// 21 bits per axis, offset to be positive: ±10⁶ cells, ample for cells of nanometres
// over any cell-sized system (positions beyond are clamped into the outermost cells,
// which only adds candidates).
std::uint64_t TriangleCells::keyOf(std::int64_t i, std::int64_t j, std::int64_t k) {
  constexpr std::int64_t kBias = std::int64_t{1} << 20;
  const auto field = [](std::int64_t v) {
    return static_cast<std::uint64_t>(std::clamp<std::int64_t>(v + kBias, 0, 2 * kBias - 1));
  };
  return (field(i) << 42) | (field(j) << 21) | field(k);
}

TriangleCells::TriangleCells(const std::vector<Vec3>& x, const std::vector<Tri>& triangles, double reach) {
  std::vector<Vec3> centroid(triangles.size());
  double spread = 0.0;
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const Tri& t = triangles[f];
    centroid[f] = (x[t[0]] + x[t[1]] + x[t[2]]) / 3.0;
    if (!centroid[f].allFinite()) continue;  // not a place: left out of every query
    for (int k = 0; k < 3; ++k) spread = std::max(spread, (x[t[k]] - centroid[f]).norm());
  }
  cell_ = reach + spread;
  if (!std::isfinite(cell_) || !(cell_ > 0.0)) {
    cell_ = 1.0;
    return;  // no usable geometry: no candidates
  }
  items_.reserve(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    if (!centroid[f].allFinite()) continue;
    const auto c = cellOf(centroid[f]);
    items_.emplace_back(keyOf(c[0], c[1], c[2]), static_cast<Index>(f));
  }
  std::sort(items_.begin(), items_.end());
}

}  // namespace cortex
