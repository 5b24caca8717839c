#include "mesh/mesh_improvement.hpp"

#include <cmath>

namespace cortex {
namespace {

Vec3 normalOf(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

int targetValence(const SurfaceMesh& m, Index v) { return m.isBoundaryVertex(v) ? 4 : 6; }

// cot of the angle at `apex` in the triangle (apex, a, b).
double cotAt(const Vec3& apex, const Vec3& a, const Vec3& b) {
  const Vec3 u = a - apex, v = b - apex;
  return u.dot(v) / u.cross(v).norm();
}

// Angles opposite an edge summing to more than pi <=> their cotangents sum below zero
// (the edge is not Delaunay).
bool isDelaunay(const Vec3& a, const Vec3& b, const Vec3& opposite1, const Vec3& opposite2) {
  return cotAt(opposite1, a, b) + cotAt(opposite2, a, b) >= -1e-12;
}

// The quad a-c-b-d stays convex seen along its normal: the flipped pair does not fold.
bool flipKeepsOrientation(const std::vector<Vec3>& p, Index a, Index b, Index c, Index d) {
  const Vec3 old_normal = normalOf(p[a], p[b], p[c]) + normalOf(p[b], p[a], p[d]);
  return normalOf(p[d], p[c], p[a]).dot(old_normal) > 0 && normalOf(p[c], p[d], p[b]).dot(old_normal) > 0;
}

std::vector<int> valences(const SurfaceMesh& m) {
  std::vector<int> val(m.numVertices(), 0);
  for (Index h = 0; h < m.numHalfedges(); ++h)
    if (!m.isDeletedHalfedge(h)) ++val[m.tail(h)];
  return val;
}

// Cheap necessary conditions for a flip (SurfaceMesh::flip checks them all again).
bool mayFlip(const SurfaceMesh& m, Index h, const std::vector<int>& val) {
  const Index t = m.twin(h);
  return !m.isBoundaryHalfedge(h) && !m.isBoundaryHalfedge(t) && val[m.tail(h)] > 3 && val[m.tip(h)] > 3 &&
         m.tip(m.next(h)) != m.tip(m.next(t));
}

// One sweep over the interior edges: flips edge a-b of triangles (a,b,c), (b,a,d) into
// c-d wherever wanted(a, b, c, d, valences) says so and the flipped pair does not fold.
template <class Wanted>
Index flipWhere(SurfaceMesh& m, Wanted wanted, const FlipObserver& on_flip) {
  Index flips = 0;
  const auto& p = m.positions();
  std::vector<int> val = valences(m);
  for (Index h = 0; h < m.numHalfedges(); ++h) {
    const Index t = m.twin(h);
    if (h > t || !mayFlip(m, h, val)) continue;
    const Index a = m.tail(h), b = m.tip(h), c = m.tip(m.next(h)), d = m.tip(m.next(t));
    if (!wanted(a, b, c, d, val) || !flipKeepsOrientation(p, a, b, c, d) || !m.flip(h)) continue;
    --val[a], --val[b], ++val[c], ++val[d];
    ++flips;
    if (on_flip) on_flip(a, b, c, d);
  }
  return flips;
}

}  // namespace

Index equalizeValences(SurfaceMesh& m, bool keep_delaunay, const FlipObserver& on_flip) {
  const auto& p = m.positions();
  return flipWhere(m, [&](Index a, Index b, Index c, Index d, const std::vector<int>& val) {
    auto deviation = [&](int da, int db, int dc, int dd) {
      const int va = val[a] + da - targetValence(m, a), vb = val[b] + db - targetValence(m, b);
      const int vc = val[c] + dc - targetValence(m, c), vd = val[d] + dd - targetValence(m, d);
      return va * va + vb * vb + vc * vc + vd * vd;
    };
    // With keep_delaunay the new edge c-d must itself be Delaunay, or a Delaunay sweep
    // would undo the flip.
    return deviation(-1, -1, 1, 1) < deviation(0, 0, 0, 0) && (!keep_delaunay || isDelaunay(p[c], p[d], p[a], p[b]));
  }, on_flip);
}

Index flipToDelaunay(SurfaceMesh& m, const FlipObserver& on_flip) {
  const auto& p = m.positions();
  return flipWhere(m, [&](Index a, Index b, Index c, Index d, const std::vector<int>&) {
    return !isDelaunay(p[a], p[b], p[c], p[d]);
  }, on_flip);
}

void smoothTangentially(SurfaceMesh& m, const SurfaceProjector& project, double step) {
  std::vector<Vec3>& p = m.positions();
  std::vector<Vec3> moved = p;
  for (Index v = 0; v < m.numVertices(); ++v) {
    if (m.isBoundaryVertex(v)) continue;
    Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
    Index count = 0;
    for (const Index h : m.outgoingHalfedges(v)) {
      centroid += p[m.tip(h)];
      normal += normalOf(p[v], p[m.tip(h)], p[m.tip(m.next(h))]);
      ++count;
    }
    const double len = normal.norm();
    if (!(len > 0.0)) continue;  // degenerate 1-ring: leave the vertex where it is
    normal /= len;
    Vec3 shift = centroid / count - p[v];
    shift -= normal * normal.dot(shift);
    moved[v] = project(p[v] + step * shift);
  }
  p.swap(moved);
}

void improveMesh(SurfaceMesh& m, const SurfaceProjector& project, int rounds) {
  for (int r = 0; r < rounds; ++r) {
    const Index flips = equalizeValences(m);
    for (int s = 0; s < 5; ++s) smoothTangentially(m, project, 0.5);
    if (flips == 0) break;
  }
}

}  // namespace cortex
