// Triangles of a mesh by the cell of their centroid, for "which triangles come within r of
// this point" queries: a triangle with a point within `reach` of p has its centroid within
// reach + (the mesh's largest centroid–vertex distance) of p, so with cells that large the
// 27 cells about p's hold every such triangle (and some farther ones, which callers
// filter by their exact distance).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace cortex {

class TriangleCells {
 public:
  TriangleCells() = default;
  TriangleCells(const std::vector<Vec3>& x, const std::vector<Tri>& triangles, double reach);

  // Calls visit(face) once for every triangle that may come within `reach` of p, in no
  // particular order.
  template <class Visit>
  void near(const Vec3& p, Visit&& visit) const {
    if (items_.empty() || !p.allFinite()) return;
    const auto c = cellOf(p);
    for (std::int64_t i = -1; i <= 1; ++i)
      for (std::int64_t j = -1; j <= 1; ++j)
        for (std::int64_t k = -1; k <= 1; ++k) {
          const std::uint64_t key = keyOf(c[0] + i, c[1] + j, c[2] + k);
          auto it = std::lower_bound(items_.begin(), items_.end(), std::pair<std::uint64_t, Index>{key, 0});
          for (; it != items_.end() && it->first == key; ++it) visit(it->second);
        }
  }

 private:
  std::array<std::int64_t, 3> cellOf(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p[0] / cell_)), static_cast<std::int64_t>(std::floor(p[1] / cell_)),
            static_cast<std::int64_t>(std::floor(p[2] / cell_))};
  }
  static std::uint64_t keyOf(std::int64_t i, std::int64_t j, std::int64_t k);

  double cell_ = 1.0;
  std::vector<std::pair<std::uint64_t, Index>> items_;  // (cell key, triangle), sorted
};

}  // namespace cortex
