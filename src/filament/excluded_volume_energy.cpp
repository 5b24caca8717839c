#include "filament/excluded_volume_energy.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "filament/cell_grid.hpp"

namespace cortex {
namespace {

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

// Below this squared length (nm^2) a segment is a point.
constexpr double kPointSegment = 1e-20;
// Below this value of sin^2 of their angle two segments are parallel: a e - b^2 loses
// all its digits to cancellation well before this.
constexpr double kParallel = 1e-12;
// Closer than this (nm) the direction between two segments is taken from their axes.
constexpr double kCoincident = 1e-12;

// A unit vector normal to both axes when they are not parallel, else normal to the one
// that is not degenerate: where two segments touch, the push has to go somewhere, and
// the same way on every call.
Vec3 separationDirection(const Vec3& u, const Vec3& v) {
  Vec3 n = u.cross(v);
  if (n.squaredNorm() > kParallel * u.squaredNorm() * v.squaredNorm() && n.squaredNorm() > 0.0) return n.normalized();
  const Vec3 axis = u.squaredNorm() >= v.squaredNorm() ? u : v;
  if (axis.squaredNorm() <= kPointSegment) return Vec3::UnitX();
  Eigen::Index smallest;
  axis.cwiseAbs().minCoeff(&smallest);
  return axis.cross(Vec3::Unit(smallest)).normalized();
}

std::uint64_t pairKey(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

// Ericson, Real-Time Collision Detection, 5.1.9: minimize over s with t eliminated, then
// clamp t and re-minimize s. Parallel segments fall back to s = 0, which still yields a
// minimizer after the clamping steps.
SegmentClosestPoints closestPoints(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= kPointSegment && e <= kPointSegment) {
    // both points
  } else if (a <= kPointSegment) {
    t = clamp01(f / e);
  } else {
    const double c = d1.dot(r);
    if (e <= kPointSegment) {
      s = clamp01(-c / a);
    } else {
      const double b = d1.dot(d2);
      const double denom = a * e - b * b;
      s = denom > kParallel * a * e ? clamp01((b * f - c * e) / denom) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = clamp01(-c / a);
      } else if (t > 1.0) {
        t = 1.0;
        s = clamp01((b - c) / a);
      }
    }
  }
  return {s, t, (p0 + s * d1) - (q0 + t * d2)};
}

PairExclusion pairExclusion(const FilamentType& a, const FilamentType& b) {
  return {0.5 * (a.excluded_volume_stiffness + b.excluded_volume_stiffness),
          0.5 * (a.excluded_volume_distance + b.excluded_volume_distance)};
}

std::optional<CylinderContact> cylinderContact(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1,
                                               const PairExclusion& pair) {
  const SegmentClosestPoints cp = closestPoints(p0, p1, q0, q1);
  const double d2 = cp.delta.squaredNorm();
  if (d2 >= pair.distance * pair.distance) return std::nullopt;
  const double d = std::sqrt(d2);
  const double overlap = pair.distance - d;
  const Vec3 dir = d > kCoincident ? Vec3(cp.delta / d) : separationDirection(p1 - p0, q1 - q0);
  return CylinderContact{0.5 * pair.stiffness * overlap * overlap, (pair.stiffness * overlap) * dir, cp.s, cp.t};
}

CylinderExclusionEnergy::CylinderExclusionEnergy(const FilamentLayout& layout, const std::vector<FilamentType>& types,
                                                 double skin)
    : FilamentTerm(layout, "excluded_volume"), types_(types), skin_(skin) {}

double CylinderExclusionEnergy::displacements(const double* x) {
  if (!built_ || built_version_ != layout_.version || built_offset_ != layout_.bead_offset ||
      built_x_.size() != 3 * static_cast<std::size_t>(layout_.num_beads))
    return INFINITY;
  moved_.resize(built_x_.size() / 3);
  double max = 0.0;
  for (std::size_t b = 0; b < built_x_.size(); b += 3) {
    const double dx = x[b] - built_x_[b], dy = x[b + 1] - built_x_[b + 1], dz = x[b + 2] - built_x_[b + 2];
    moved_[b / 3] = std::sqrt(dx * dx + dy * dy + dz * dz);
    max = std::max(max, moved_[b / 3]);
  }
  return max;
}

void CylinderExclusionEnergy::rebuild(const double* x) {
  ++rebuilds_;
  built_ = true;
  built_version_ = layout_.version;
  built_offset_ = layout_.bead_offset;
  built_x_.assign(x, x + 3 * static_cast<std::size_t>(layout_.num_beads));
  pairs_.clear();
  const std::vector<Cylinder>& cyl = layout_.cylinders;
  const Index n = static_cast<Index>(cyl.size());
  if (n < 2) return;
  auto bead = [x](Index b) { return Eigen::Map<const Vec3>(x + 3 * b); };

  // The daughter's first cylinder starts on its mother cylinder: the branch joint, not
  // steric repulsion, holds that pair.
  excluded_.clear();
  if (!layout_.branches.empty()) {
    cell_of_.assign(static_cast<std::size_t>(layout_.num_beads), -1);  // cylinder by its bead0
    for (Index i = 0; i < n; ++i) cell_of_[cyl[i].bead0] = i;
    for (const BranchJoint& j : layout_.branches) {
      const Index mother = cell_of_[j.mother.bead0], daughter = cell_of_[j.daughter0];
      if (mother >= 0 && daughter >= 0) excluded_.push_back(pairKey(mother, daughter));
    }
    std::sort(excluded_.begin(), excluded_.end());
  }

  // Midpoints of a pair within distance d of each other are within d + (La + Lb)/2.
  midpoint_.resize(cyl.size());
  half_length_.resize(cyl.size());
  double max_length = 0.0, max_d0 = 0.0;
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (Index i = 0; i < n; ++i) {
    const Vec3 a = bead(cyl[i].bead0), b = bead(cyl[i].bead1);
    midpoint_[i] = 0.5 * (a + b);
    half_length_[i] = 0.5 * (b - a).norm();
    max_length = std::max(max_length, 2.0 * half_length_[i]);
    max_d0 = std::max(max_d0, types_[cyl[i].type].excluded_volume_distance);
    lo = lo.cwiseMin(midpoint_[i]);
    hi = hi.cwiseMax(midpoint_[i]);
  }
  const GridShape grid = gridShape(lo, hi, max_d0 + skin_ + max_length, n);
  const double cell = grid.cell;
  const std::array<Index, 3>& dims = grid.dims;
  const Index num_cells = dims[0] * dims[1] * dims[2];
  auto cellCoord = [&](Index i, int k) {
    return std::min(dims[k] - 1, static_cast<Index>((midpoint_[i][k] - lo[k]) / cell));
  };

  // Counting sort of cylinders by cell.
  cell_of_.resize(cyl.size());
  cell_start_.assign(static_cast<std::size_t>(num_cells) + 1, 0);
  for (Index i = 0; i < n; ++i) {
    cell_of_[i] = (cellCoord(i, 2) * dims[1] + cellCoord(i, 1)) * dims[0] + cellCoord(i, 0);
    ++cell_start_[cell_of_[i] + 1];
  }
  for (Index c = 0; c < num_cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_items_.resize(cyl.size());
  cursor_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (Index i = 0; i < n; ++i) cell_items_[cursor_[cell_of_[i]]++] = i;

  for (Index i = 0; i < n; ++i) {
    const std::size_t first_pair = pairs_.size();
    const Cylinder& ci = cyl[i];
    const Vec3 a0 = bead(ci.bead0), a1 = bead(ci.bead1);
    const FilamentType& ti = types_[ci.type];
    const Index cx = cellCoord(i, 0), cy = cellCoord(i, 1), cz = cellCoord(i, 2);
    for (Index z = std::max(0, cz - 1); z <= std::min(dims[2] - 1, cz + 1); ++z)
      for (Index y = std::max(0, cy - 1); y <= std::min(dims[1] - 1, cy + 1); ++y)
        for (Index xc = std::max(0, cx - 1); xc <= std::min(dims[0] - 1, cx + 1); ++xc) {
          const Index c = (z * dims[1] + y) * dims[0] + xc;
          for (Index k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
            const Index j = cell_items_[k];
            if (j <= i) continue;
            const Cylinder& cj = cyl[j];
            if (ci.bead0 == cj.bead0 || ci.bead0 == cj.bead1 || ci.bead1 == cj.bead0 || ci.bead1 == cj.bead1) continue;
            const PairExclusion exclusion = pairExclusion(ti, types_[cj.type]);
            const double reach = exclusion.distance + skin_;
            const double mid_reach = reach + half_length_[i] + half_length_[j];
            if ((midpoint_[i] - midpoint_[j]).squaredNorm() > mid_reach * mid_reach) continue;
            const double d2 = closestPoints(a0, a1, bead(cj.bead0), bead(cj.bead1)).delta.squaredNorm();
            if (d2 >= reach * reach) continue;
            if (!excluded_.empty() && std::binary_search(excluded_.begin(), excluded_.end(), pairKey(i, j))) continue;
            pairs_.push_back({i, j, exclusion, std::sqrt(d2)});
          }
        }
    // Pairs in (i, j) order whatever the cells were: sums over the list then depend only
    // on the positions, not on where the list was last built.
    std::sort(pairs_.begin() + static_cast<std::ptrdiff_t>(first_pair), pairs_.end(),
              [](const Pair& p, const Pair& q) { return p.b < q.b; });
  }
}

// With the closest-point parameters s, t held fixed (envelope theorem), delta = p - q is
// linear in the four beads: dE/d(delta) = -k (d0 - d) delta/d = -push, shared by the
// weights.
double CylinderExclusionEnergy::evaluate(const Evaluation& e) {
  const double* x = e.x + 3 * static_cast<std::size_t>(layout_.bead_offset);
  double* g = e.gradient ? e.gradient + 3 * static_cast<std::size_t>(layout_.bead_offset) : nullptr;
  if (displacements(x) > 0.5 * skin_) {
    rebuild(x);
    moved_.assign(built_x_.size() / 3, 0.0);
  }
  auto bead = [x](Index b) { return Eigen::Map<const Vec3>(x + 3 * b); };
  const std::vector<Cylinder>& cyl = layout_.cylinders;
  double energy = 0.0;
  for (const Pair& p : pairs_) {
    const Cylinder &ca = cyl[p.a], &cb = cyl[p.b];
    // A point of a segment moved at most as far as the farther of its two beads, so the
    // pair's distance shrank by at most the sum of those since the build: pairs that
    // were far enough apart then are still out of range, without their closest points.
    const double shrink = std::max(moved_[ca.bead0], moved_[ca.bead1]) + std::max(moved_[cb.bead0], moved_[cb.bead1]);
    if (p.built - shrink >= p.exclusion.distance) continue;
    const std::optional<CylinderContact> c =
        cylinderContact(bead(ca.bead0), bead(ca.bead1), bead(cb.bead0), bead(cb.bead1), p.exclusion);
    if (!c) continue;
    energy += c->energy;
    if (!g) continue;
    Eigen::Map<Vec3>(g + 3 * ca.bead0) -= (1.0 - c->s) * c->push;
    Eigen::Map<Vec3>(g + 3 * ca.bead1) -= c->s * c->push;
    Eigen::Map<Vec3>(g + 3 * cb.bead0) += (1.0 - c->t) * c->push;
    Eigen::Map<Vec3>(g + 3 * cb.bead1) += c->t * c->push;
  }
  return energy;
}

}  // namespace cortex
