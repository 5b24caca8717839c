#include "interact/membrane_bead_exclusion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "interact/triangle_cells.hpp"
#include "interact/triangle_inverse_fourth.hpp"
#include "interact/triangle_queries.hpp"

namespace cortex {
namespace {

// The skin of the Verlet list, as a fraction of the cut-off: larger lists fewer rebuilds.
constexpr double kSkinFraction = 0.5;
// Pairs fade out smoothly from this fraction of the cut-off to the cut-off.
constexpr double kFadeStart = 0.5;

}  // namespace

MembraneBeadExclusion::MembraneBeadExclusion(const Membrane& membrane, const FilamentNetwork& network,
                                             MembraneBeadExclusionParams params)
    : membrane_(membrane), network_(network), params_(params), skin_(kSkinFraction * params.cutoff) {}

const std::string& MembraneBeadExclusion::name() const {
  static const std::string kName = "filament_exclusion";
  return kName;
}

void MembraneBeadExclusion::gatherPositions(const Evaluation& e) {
  // Which beads: chosen again whenever the network's layout changed (growth added a bead,
  // a branch a filament).
  const bool relaid = !built_ || network_.layout().version != built_layout_;
  if (relaid) {
    beads_.clear();
    const auto& filaments = network_.filaments();
    for (std::size_t f = 0; f < filaments.size(); ++f) {
      const Index first = network_.firstBead(static_cast<Index>(f));
      const Index last = first + static_cast<Index>(filaments[f].beads.size()) - 1;
      switch (params_.beads) {
        case ExclusionBeads::kAll:
          for (Index b = first; b <= last; ++b) beads_.push_back(b);
          break;
        case ExclusionBeads::kEnds:
          beads_.push_back(first);
          if (last != first) beads_.push_back(last);
          break;
        case ExclusionBeads::kPlusEnds: beads_.push_back(last); break;
      }
    }
    built_ = false;
  }
  // What was read from the bodies at the last evaluation still holds.
  const bool kept = !relaid && e.held != 0 && e.held == held_;
  held_ = e.held;
  if (e.moves(membrane_)) {
    const Index nv = membrane_.mesh().numVertices();
    vertex_x_.resize(static_cast<std::size_t>(nv));
    const double* x = e.x + 3 * membrane_.offset();
    for (Index v = 0; v < nv; ++v) vertex_x_[v] = Vec3(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
    vertex_move_ = -1.0;
  } else if (!kept) {
    vertex_x_ = membrane_.mesh().positions();
    vertex_move_ = -1.0;
  }
  // Where the network holds its beads: the positions when they do not move here, and
  // the side of the membrane they were on (crossesSinceHeld).
  if (!kept) {
    held_beads_.resize(3 * static_cast<std::size_t>(network_.numPoints()));
    network_.gather(held_beads_.data());
  }
  if (kept && !e.moves(network_)) return;
  bead_x_.resize(beads_.size());
  const double* x = e.moves(network_) ? e.x + 3 * network_.offset() : held_beads_.data();
  for (std::size_t i = 0; i < beads_.size(); ++i) {
    const double* b = x + 3 * beads_[i];
    bead_x_[i] = Vec3(b[0], b[1], b[2]);
  }
  bead_move_ = -1.0;
}

bool MembraneBeadExclusion::listIsStale() {
  if (!built_ || membrane_.connectivityVersion() != built_connectivity_ ||
      built_vertex_x_.size() != vertex_x_.size() || built_bead_x_.size() != bead_x_.size())
    return true;
  const auto largestMove = [](const std::vector<Vec3>& now, const std::vector<Vec3>& then) {
    double move = 0.0;
    for (std::size_t i = 0; i < now.size(); ++i) move = std::max(move, (now[i] - then[i]).squaredNorm());
    return std::sqrt(move);
  };
  if (vertex_move_ < 0.0) vertex_move_ = largestMove(vertex_x_, built_vertex_x_);
  if (bead_move_ < 0.0) bead_move_ = largestMove(bead_x_, built_bead_x_);
  return !(vertex_move_ + bead_move_ < skin_);
}

void MembraneBeadExclusion::rebuild() {
  ++rebuilds_;
  const auto& triangles = membrane_.topology().triangles;
  const double reach = params_.cutoff + skin_, reach2 = reach * reach;
  // The cells index the triangles as they were at the last build: beads that moved past
  // the skin under a held membrane (a filament relaxation) need new pairs, not new cells.
  const bool same_triangles =
      built_ && built_connectivity_ == membrane_.connectivityVersion() && built_vertex_x_ == vertex_x_;
  if (!same_triangles) cells_ = TriangleCells(vertex_x_, triangles, reach);
  built_ = true;
  built_connectivity_ = membrane_.connectivityVersion();
  built_layout_ = network_.layout().version;
  built_vertex_x_ = vertex_x_;
  built_bead_x_ = bead_x_;
  vertex_move_ = bead_move_ = 0.0;
  pairs_.clear();
  for (std::size_t b = 0; b < bead_x_.size(); ++b) {
    const Vec3& p = bead_x_[b];
    cells_.near(p, [&](Index f) {
      const Tri& t = triangles[f];
      if ((closestPointOnTriangle(p, vertex_x_[t[0]], vertex_x_[t[1]], vertex_x_[t[2]]).point - p).squaredNorm() <
          reach2)
        pairs_.push_back({f, static_cast<Index>(b)});
    });
  }
  std::sort(pairs_.begin(), pairs_.end(),
            [](const Pair& x, const Pair& y) { return x.face != y.face ? x.face < y.face : x.bead < y.bead; });
}

MembraneBeadExclusion::PairEnergy MembraneBeadExclusion::pairEnergy(
    const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, std::optional<InverseFourthGradient> gradient) const {
  PairEnergy out;
  const double k = params_.stiffness, cutoff = params_.cutoff, fade_start = kFadeStart * cutoff;
  const TrianglePoint nearest = closestPointOnTriangle(p, a, b, c);
  const double distance = (p - nearest.point).norm();
  if (!(distance < cutoff)) return out;
  out.active = true;
  // The fade S(x) = 1 − 10x³ + 15x⁴ − 6x⁵ over x = (distance − fade_start)/(cutoff − fade_start):
  // C² in the distance, which is C¹ in the positions, so the energy has continuous forces.
  double fade = 1.0, fade_slope = 0.0;
  if (distance > fade_start) {
    const double width = cutoff - fade_start, x = (distance - fade_start) / width;
    fade = 1.0 - x * x * x * (10.0 - x * (15.0 - 6.0 * x));
    fade_slope = -30.0 * x * x * (1.0 - x) * (1.0 - x) / width;
  }
  if (!gradient) {
    out.energy = k * fade * triangleInverseFourth(p, a, b, c);
    return out;
  }
  const TriangleInverseFourth r = triangleInverseFourthWithGradient(p, a, b, c, *gradient);
  out.energy = k * fade * r.value;
  if (!std::isfinite(r.value)) return out;
  // ∇(S I) = S ∇I + I S' ∇distance; ∇_p distance = n̂, ∇_vertex i distance = −w_i n̂.
  const Vec3 away = fade_slope != 0.0 ? Vec3(k * r.value * fade_slope * (p - nearest.point) / distance) : Vec3::Zero();
  out.d_point = k * fade * r.d_point + away;
  if (*gradient == InverseFourthGradient::kAll)
    for (int v = 0; v < 3; ++v) out.d_vertices[v] = k * fade * r.d_vertices[v] - nearest.weight[v] * away;
  return out;
}

Vec3 MembraneBeadExclusion::forceAt(const Vec3& p, const TriangleCells& held) const {
  const auto& x = membrane_.mesh().positions();
  const auto& triangles = membrane_.topology().triangles;
  std::vector<Index> faces;
  held.near(p, [&](Index f) { faces.push_back(f); });
  std::sort(faces.begin(), faces.end());  // summed in one order, whatever the cells'
  Vec3 force = Vec3::Zero();
  for (Index f : faces) {
    const Tri& t = triangles[f];
    const PairEnergy pe = pairEnergy(p, x[t[0]], x[t[1]], x[t[2]], InverseFourthGradient::kPoint);
    if (pe.active) force -= pe.d_point;
  }
  return force;
}

TriangleCells MembraneBeadExclusion::heldCells() const {
  return TriangleCells(membrane_.mesh().positions(), membrane_.topology().triangles, params_.cutoff);
}

bool MembraneBeadExclusion::crossesSinceHeld(const Evaluation& e) {
  if (!e.moves(membrane_) && !e.moves(network_)) return false;
  const std::vector<Vec3>& held_vertices = membrane_.mesh().positions();
  if (held_vertices.size() != vertex_x_.size()) return false;  // remeshed since: nothing to compare with
  const auto& triangles = membrane_.topology().triangles;
  for (const Pair& pair : pairs_) {
    const Tri& t = triangles[pair.face];
    const Vec3& p = bead_x_[pair.bead];
    const Vec3 a = vertex_x_[t[0]], b = vertex_x_[t[1]], c = vertex_x_[t[2]];
    // Only where the bead lies over the triangle (its foot inside): elsewhere a change of
    // side is the bead passing beside the triangle, seen by the neighbour it is over.
    const Vec3 n = (b - a).cross(c - a);
    const Vec3 q = p - (p - a).dot(n) / n.squaredNorm() * n;
    if ((b - a).cross(q - a).dot(n) < 0 || (c - b).cross(q - b).dot(n) < 0 || (a - c).cross(q - c).dot(n) < 0) continue;
    const Vec3 p0 = Eigen::Map<const Vec3>(held_beads_.data() + 3 * beads_[pair.bead]);
    const Vec3 &a0 = held_vertices[t[0]], &b0 = held_vertices[t[1]], &c0 = held_vertices[t[2]];
    const double side = (p - a).dot(n), held_side = (p0 - a0).dot((b0 - a0).cross(c0 - a0));
    if ((side > 0 && held_side < 0) || (side < 0 && held_side > 0)) return true;
  }
  return false;
}

double MembraneBeadExclusion::evaluate(const Evaluation& e) {
  gatherPositions(e);
  for (const Vec3& p : bead_x_)
    if (!p.allFinite()) return std::numeric_limits<double>::infinity();
  if (listIsStale()) rebuild();
  if (crossesSinceHeld(e)) return std::numeric_limits<double>::infinity();
  double* vertex_gradient = e.gradient && e.moves(membrane_) ? e.gradient + 3 * membrane_.offset() : nullptr;
  double* bead_gradient = e.gradient && e.moves(network_) ? e.gradient + 3 * network_.offset() : nullptr;
  // Derivatives only along what moves: a filament relaxation under a held membrane needs
  // the beads' (the kernel's automatic differentiation in 4 directions instead of 12).
  std::optional<InverseFourthGradient> gradient;
  if (vertex_gradient) gradient = InverseFourthGradient::kAll;
  else if (bead_gradient) gradient = InverseFourthGradient::kPoint;
  const auto& triangles = membrane_.topology().triangles;
  double energy = 0.0;
  active_pairs_ = 0;
  for (const Pair& pair : pairs_) {
    const Tri& t = triangles[pair.face];
    const PairEnergy pe = pairEnergy(bead_x_[pair.bead], vertex_x_[t[0]], vertex_x_[t[1]], vertex_x_[t[2]], gradient);
    if (!pe.active) continue;
    ++active_pairs_;
    if (!std::isfinite(pe.energy)) return std::numeric_limits<double>::infinity();
    energy += pe.energy;
    if (bead_gradient)
      for (int i = 0; i < 3; ++i) bead_gradient[3 * beads_[pair.bead] + i] += pe.d_point[i];
    if (vertex_gradient)
      for (int v = 0; v < 3; ++v)
        for (int i = 0; i < 3; ++i) vertex_gradient[3 * t[v] + i] += pe.d_vertices[v][i];
  }
  return energy;
}

}  // namespace cortex
