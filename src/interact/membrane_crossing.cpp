#include "interact/membrane_crossing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interact/triangle_queries.hpp"

namespace cortex {

std::string MembraneCrossing::describe(const Membrane& membrane) const {
  return fmt::format("filament {} (cylinder {}) passes through membrane \"{}\" (triangle {})", filament, cylinder,
                     membrane.name(), face);
}

std::optional<MembraneCrossing> findMembraneCrossing(const Membrane& membrane, const FilamentNetwork& network) {
  const auto& x = membrane.mesh().positions();
  const auto& triangles = membrane.topology().triangles;
  if (triangles.empty()) return std::nullopt;
  // Triangles by the cell of their centroid; a cylinder can only meet triangles whose
  // centroid lies within (its half length + the triangles' largest centroid–vertex
  // distance) of its midpoint, so cells that large and the 27 about the midpoint suffice.
  std::vector<Vec3> centroid(triangles.size());
  double spread = 0.0, half_length = 0.0;
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const Tri& t = triangles[f];
    centroid[f] = (x[t[0]] + x[t[1]] + x[t[2]]) / 3.0;
    for (int k = 0; k < 3; ++k) spread = std::max(spread, (x[t[k]] - centroid[f]).norm());
  }
  for (const Filament& fil : network.filaments())
    for (std::size_t i = 0; i + 1 < fil.beads.size(); ++i)
      half_length = std::max(half_length, 0.5 * (fil.beads[i + 1] - fil.beads[i]).norm());
  const double cell = half_length + spread + 1e-9;
  const auto cellOf = [&](const Vec3& p) {
    return std::array<std::int64_t, 3>{static_cast<std::int64_t>(std::floor(p[0] / cell)),
                                       static_cast<std::int64_t>(std::floor(p[1] / cell)),
                                       static_cast<std::int64_t>(std::floor(p[2] / cell))};
  };
  std::vector<std::pair<std::array<std::int64_t, 3>, Index>> by_cell(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) by_cell[f] = {cellOf(centroid[f]), static_cast<Index>(f)};
  std::sort(by_cell.begin(), by_cell.end());
  const auto& filaments = network.filaments();
  for (std::size_t fi = 0; fi < filaments.size(); ++fi) {
    const auto& beads = filaments[fi].beads;
    for (std::size_t i = 0; i + 1 < beads.size(); ++i) {
      const Vec3 &p = beads[i], &q = beads[i + 1];
      if (!p.allFinite() || !q.allFinite()) continue;
      const auto c = cellOf(0.5 * (p + q));
      std::optional<Index> first;
      for (std::int64_t di = -1; di <= 1; ++di)
        for (std::int64_t dj = -1; dj <= 1; ++dj)
          for (std::int64_t dk = -1; dk <= 1; ++dk) {
            const std::array<std::int64_t, 3> key{c[0] + di, c[1] + dj, c[2] + dk};
            auto it = std::lower_bound(by_cell.begin(), by_cell.end(), std::pair{key, Index{0}});
            for (; it != by_cell.end() && it->first == key; ++it) {
              const Tri& t = triangles[it->second];
              if (segmentMeetsTriangle(p, q, x[t[0]], x[t[1]], x[t[2]]) && (!first || it->second < *first))
                first = it->second;
            }
          }
      if (first) return MembraneCrossing{static_cast<Index>(fi), static_cast<Index>(i), *first};
    }
  }
  return std::nullopt;
}

}  // namespace cortex
