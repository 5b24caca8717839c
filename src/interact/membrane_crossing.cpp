#include "interact/membrane_crossing.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "interact/triangle_cells.hpp"
#include "interact/triangle_queries.hpp"

namespace cortex {

std::string MembraneCrossing::describe(const Membrane& membrane) const {
  return fmt::format("filament {} (cylinder {}) passes through membrane \"{}\" (triangle {})", filament, cylinder,
                     membrane.name(), face);
}

std::optional<MembraneCrossing> findMembraneCrossing(const Membrane& membrane, const FilamentNetwork& network) {
  const auto& x = membrane.mesh().positions();
  const auto& triangles = membrane.topology().triangles;
  // A cylinder meets only triangles within its half length of its midpoint.
  double half_length = 0.0;
  for (const Filament& fil : network.filaments())
    for (std::size_t i = 0; i + 1 < fil.beads.size(); ++i)
      half_length = std::max(half_length, 0.5 * (fil.beads[i + 1] - fil.beads[i]).norm());
  const TriangleCells cells(x, triangles, half_length);
  const auto& filaments = network.filaments();
  for (std::size_t fi = 0; fi < filaments.size(); ++fi) {
    const auto& beads = filaments[fi].beads;
    for (std::size_t i = 0; i + 1 < beads.size(); ++i) {
      const Vec3 &p = beads[i], &q = beads[i + 1];
      if (!p.allFinite() || !q.allFinite()) continue;
      std::optional<Index> first;
      cells.near(0.5 * (p + q), [&](Index f) {
        const Tri& t = triangles[f];
        if ((!first || f < *first) && segmentMeetsTriangle(p, q, x[t[0]], x[t[1]], x[t[2]])) first = f;
      });
      if (first) return MembraneCrossing{static_cast<Index>(fi), static_cast<Index>(i), *first};
    }
  }
  return std::nullopt;
}

}  // namespace cortex
