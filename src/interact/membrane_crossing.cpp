#include "interact/membrane_crossing.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "interact/triangle_cells.hpp"
#include "interact/triangle_queries.hpp"

namespace cortex {

std::string MembraneCrossing::describe(const Membrane& membrane) const {
  return fmt::format("filament {} (cylinder {}) passes through membrane \"{}\" (triangle {})", filament, cylinder,
                     membrane.name(), face);
}

bool segmentMeetsMembrane(const Membrane& membrane, const Vec3& p, const Vec3& q) {
  const auto& x = membrane.mesh().positions();
  const Eigen::AlignedBox3d segment(p.cwiseMin(q), p.cwiseMax(q));
  for (const Tri& t : membrane.topology().triangles) {
    Eigen::AlignedBox3d box(x[t[0]]);
    box.extend(x[t[1]]).extend(x[t[2]]);
    if (box.intersects(segment) && segmentMeetsTriangle(p, q, x[t[0]], x[t[1]], x[t[2]])) return true;
  }
  return false;
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

namespace {

// The first edge of `a` (as triangle, corner) meeting a triangle of `b`, described.
std::optional<std::string> edgeThrough(const Membrane& a, const Membrane& b) {
  const auto& xa = a.mesh().positions();
  const auto& xb = b.mesh().positions();
  const auto& ta = a.topology().triangles;
  const auto& tb = b.topology().triangles;
  double half_length = 0.0;
  for (const Tri& t : ta)
    for (int k = 0; k < 3; ++k) half_length = std::max(half_length, 0.5 * (xa[t[(k + 1) % 3]] - xa[t[k]]).norm());
  const TriangleCells cells(xb, tb, half_length);
  for (const Tri& t : ta)
    for (int k = 0; k < 3; ++k) {
      const Vec3 &p = xa[t[k]], &q = xa[t[(k + 1) % 3]];
      std::optional<Index> met;
      cells.near(0.5 * (p + q), [&](Index f) {
        const Tri& u = tb[f];
        if (!met && segmentMeetsTriangle(p, q, xb[u[0]], xb[u[1]], xb[u[2]])) met = f;
      });
      if (met)
        return fmt::format("the edge of \"{}\" from ({:.4g}, {:.4g}, {:.4g}) to ({:.4g}, {:.4g}, {:.4g}) nm meets "
                           "triangle {} of \"{}\"",
                           a.name(), p[0], p[1], p[2], q[0], q[1], q[2], *met, b.name());
    }
  return std::nullopt;
}

Eigen::AlignedBox3d boundsOf(const Membrane& m) {
  Eigen::AlignedBox3d box;
  const auto& x = m.mesh().positions();
  for (const Tri& t : m.topology().triangles)
    for (Index v : t) box.extend(x[v]);
  return box;
}

}  // namespace

std::optional<std::string> findMembranesCrossing(const Membrane& a, const Membrane& b) {
  // Meshes in disjoint boxes cannot meet. Side by side, vesicles skip the edge search,
  // which was 13% of curvature_sorting's time (three vesicles, checked every window).
  if (!boundsOf(a).intersects(boundsOf(b))) return std::nullopt;
  if (auto where = edgeThrough(a, b)) return where;
  return edgeThrough(b, a);
}

std::optional<MembranesCrossing> findCrossingMembranes(const std::vector<std::unique_ptr<Membrane>>& membranes) {
  for (std::size_t i = 0; i < membranes.size(); ++i)
    for (std::size_t j = i + 1; j < membranes.size(); ++j)
      if (auto where = findMembranesCrossing(*membranes[i], *membranes[j]))
        return MembranesCrossing{membranes[i].get(), membranes[j].get(), std::move(*where)};
  return std::nullopt;
}

}  // namespace cortex
