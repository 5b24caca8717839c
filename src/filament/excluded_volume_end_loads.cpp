#include "filament/excluded_volume_end_loads.hpp"

#include <algorithm>

#include "filament/excluded_volume_energy.hpp"

namespace cortex {

CylinderExclusionEndLoads::CylinderExclusionEndLoads(const FilamentNetwork& network) : network_(network) {
  for (const FilamentType& t : network.config().types) max_distance_ = std::max(max_distance_, t.excluded_volume_distance);
}

void CylinderExclusionEndLoads::update() { boxes_.clear(); }

const CylinderExclusionEndLoads::Box& CylinderExclusionEndLoads::boxOf(Index filament) const {
  const Filament& f = network_.filaments()[filament];
  if (boxes_.size() < network_.filaments().size()) boxes_.resize(network_.filaments().size(), Box{{}, {}, {1, 0}});
  Box& box = boxes_[filament];
  if (box.ends[0] != f.minusEnd() || box.ends[1] != f.plusEnd()) {
    box.lo = box.hi = f.beads.front();
    for (const Vec3& b : f.beads) {
      box.lo = box.lo.cwiseMin(b);
      box.hi = box.hi.cwiseMax(b);
    }
    box.ends = {f.minusEnd(), f.plusEnd()};
  }
  return box;
}

bool CylinderExclusionEndLoads::branchPair(Index a, Index ca, Index b, Index cb) const {
  for (const Branch& br : network_.branches()) {
    const bool a_on_b = br.daughter == a && br.mother == b && ca == 0;
    const bool b_on_a = br.daughter == b && br.mother == a && cb == 0;
    if (!a_on_b && !b_on_a) continue;
    const Index on = network_.filaments()[br.mother].locate(network_.siteCoordinate(BinderKind::kBrancher, br.type, br.site)).first;
    if (on == (a_on_b ? cb : ca)) return true;
  }
  return false;
}

Vec3 CylinderExclusionEndLoads::forceAt(Index filament, const Vec3& point, bool plus_end) const {
  const Filament& f = network_.filaments()[filament];
  const Index n = f.numCylinders();
  if (n < 1) return Vec3::Zero();
  // The end's cylinder from its inner bead to the end bead at `point`: the end bead's
  // share of a contact at parameter s is s.
  const Index end_cylinder = plus_end ? n - 1 : 0;
  const Vec3 inner = plus_end ? f.beads[n - 1] : f.beads[1];
  const Vec3 lo = inner.cwiseMin(point).array() - max_distance_, hi = inner.cwiseMax(point).array() + max_distance_;
  const FilamentType& type = network_.type(f.type);
  Vec3 force = Vec3::Zero();
  for (Index j = 0; j < static_cast<Index>(network_.filaments().size()); ++j) {
    const Box& box = boxOf(j);
    if ((box.lo.array() > hi.array()).any() || (box.hi.array() < lo.array()).any()) continue;
    const Filament& other = network_.filaments()[j];
    const PairExclusion exclusion = pairExclusion(type, network_.type(other.type));
    for (Index c = 0; c < other.numCylinders(); ++c) {
      if (j == filament && std::abs(c - end_cylinder) <= 1) continue;  // itself, and neighbours sharing a bead
      const auto contact = cylinderContact(inner, point, other.beads[c], other.beads[c + 1], exclusion);
      if (!contact || (j != filament && branchPair(filament, end_cylinder, j, c))) continue;
      force += contact->s * contact->push;
    }
  }
  return force;
}

}  // namespace cortex
