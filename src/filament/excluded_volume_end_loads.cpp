#include "filament/excluded_volume_end_loads.hpp"

#include <algorithm>
#include <cmath>

#include "filament/cell_grid.hpp"
#include "filament/excluded_volume_energy.hpp"

namespace cortex {

CylinderExclusionEndLoads::CylinderExclusionEndLoads(const FilamentNetwork& network) : network_(network) {
  for (const FilamentType& t : network.config().types) max_distance_ = std::max(max_distance_, t.excluded_volume_distance);
}

void CylinderExclusionEndLoads::update() {
  const std::vector<Filament>& fils = network_.filaments();
  gridded_ = static_cast<Index>(fils.size());
  ends_.resize(fils.size());
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  Index cylinders = 0;
  double longest = 0.0;  // nm, the longest a cylinder can grow
  for (const FilamentType& t : network_.config().types) longest = std::max(longest, t.cylinder_monomers * t.monomer_size);
  for (const Filament& f : fils) {
    cylinders += f.numCylinders();
    for (const Vec3& b : f.beads) {
      lo = lo.cwiseMin(b);
      hi = hi.cwiseMax(b);
    }
  }
  // Cells about a cylinder long: a cylinder's padded box then touches 2-3 per axis.
  if (cylinders == 0) lo = hi = Vec3::Zero();
  const GridShape grid = gridShape(lo, hi, std::max(longest, 2.0 * max_distance_), cylinders);
  cell_ = grid.cell;
  dims_ = grid.dims;
  origin_ = lo;
  cells_.assign(static_cast<std::size_t>(dims_[0] * dims_[1] * dims_[2]), {});
  for (Index f = 0; f < gridded_; ++f) {
    for (Index c = 0; c < fils[f].numCylinders(); ++c) enlistCylinder(f, c);
    ends_[f] = {fils[f].minusEnd(), fils[f].plusEnd()};
  }
}

CylinderExclusionEndLoads::Cell CylinderExclusionEndLoads::cellOf(const Vec3& p) const {
  Cell c;
  for (int k = 0; k < 3; ++k)
    c[k] = std::clamp(static_cast<Index>(std::floor((p[k] - origin_[k]) / cell_)), Index{0}, dims_[k] - 1);
  return c;
}

void CylinderExclusionEndLoads::enlist(Index filament, const Vec3& lo, const Vec3& hi) const {
  const Cell a = cellOf(lo.array() - max_distance_), b = cellOf(hi.array() + max_distance_);
  for (Index z = a[2]; z <= b[2]; ++z)
    for (Index y = a[1]; y <= b[1]; ++y)
      for (Index x = a[0]; x <= b[0]; ++x) {
        std::vector<Index>& cell = cells_[static_cast<std::size_t>((z * dims_[1] + y) * dims_[0] + x)];
        if (std::find(cell.begin(), cell.end(), filament) == cell.end()) cell.push_back(filament);
      }
}

void CylinderExclusionEndLoads::enlistCylinder(Index filament, Index cylinder) const {
  const Filament& f = network_.filaments()[filament];
  const Vec3 &p = f.beads[cylinder], &q = f.beads[cylinder + 1];
  enlist(filament, p.cwiseMin(q), p.cwiseMax(q));
}

bool CylinderExclusionEndLoads::branchPair(Index a, Index ca, Index b, Index cb) const {
  for (const Branch& br : network_.branches()) {
    const bool a_on_b = br.daughter == a && br.mother == b && ca == 0;
    const bool b_on_a = br.daughter == b && br.mother == a && cb == 0;
    if (!a_on_b && !b_on_a) continue;
    const Index on =
        network_.filaments()[br.mother].locate(network_.siteCoordinate(BinderKind::kBrancher, br.type, br.site)).first;
    if (on == (a_on_b ? cb : ca)) return true;
  }
  return false;
}

Vec3 CylinderExclusionEndLoads::forceAt(Index filament, const Vec3& point, bool plus_end) const {
  const std::vector<Filament>& fils = network_.filaments();
  const Filament& f = fils[filament];
  const Index n = f.numCylinders();
  if (n < 1) return Vec3::Zero();
  // The end's cylinder, minus-side bead first, with the end bead at `point`.
  const Index end_cylinder = plus_end ? n - 1 : 0;
  const Vec3 e0 = plus_end ? f.beads[n - 1] : point, e1 = plus_end ? point : f.beads[1];
  // The chemistry asks after every event that moves an end: list where it now is.
  if (filament < gridded_ && (ends_[filament][0] != f.minusEnd() || ends_[filament][1] != f.plusEnd())) {
    if (!cells_.empty()) enlistCylinder(filament, end_cylinder);
    ends_[filament] = {f.minusEnd(), f.plusEnd()};
  }
  const FilamentType& type = network_.type(f.type);
  Vec3 force = Vec3::Zero();
  auto pushFrom = [&](Index j) {
    const Filament& other = fils[j];
    const PairExclusion exclusion = pairExclusion(type, network_.type(other.type));
    for (Index c = 0; c < other.numCylinders(); ++c) {
      if (j == filament && std::abs(c - end_cylinder) <= 1) continue;  // itself, and neighbours sharing a bead
      // The pair as the term takes it, the cylinder first in filament order first: where
      // two cylinders touch, the way they are pushed apart depends on that order.
      const bool end_first = filament < j || (filament == j && end_cylinder < c);
      const auto contact = end_first ? cylinderContact(e0, e1, other.beads[c], other.beads[c + 1], exclusion)
                                     : cylinderContact(other.beads[c], other.beads[c + 1], e0, e1, exclusion);
      if (!contact || (j != filament && branchPair(filament, end_cylinder, j, c))) continue;
      const double w = end_first ? contact->s : contact->t;  // the end's cylinder's weight of its plus-side bead
      const Vec3 push = end_first ? contact->push : Vec3(-contact->push);
      force += (plus_end ? w : 1.0 - w) * push;
    }
  };
  if (seen_.size() < fils.size()) seen_.resize(fils.size(), 0);
  ++query_;
  if (!cells_.empty()) {
    const Cell a = cellOf(e0.cwiseMin(e1)), b = cellOf(e0.cwiseMax(e1));
    for (Index z = a[2]; z <= b[2]; ++z)
      for (Index y = a[1]; y <= b[1]; ++y)
        for (Index x = a[0]; x <= b[0]; ++x)
          for (Index j : cells_[static_cast<std::size_t>((z * dims_[1] + y) * dims_[0] + x)])
            if (seen_[j] != query_) {
              seen_[j] = query_;
              pushFrom(j);
            }
  }
  for (Index j = gridded_; j < static_cast<Index>(fils.size()); ++j) pushFrom(j);  // created since update()
  return force;
}

}  // namespace cortex
