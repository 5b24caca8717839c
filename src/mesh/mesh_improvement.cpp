#include "mesh/mesh_improvement.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace cortex {
namespace {

Vec3 normalOf(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

int targetValence(const SurfaceMesh& m, Index v) { return m.isBoundaryVertex(v) ? 4 : 6; }

double angleAt(const Vec3& apex, const Vec3& a, const Vec3& b) {
  const Vec3 u = a - apex, v = b - apex;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// The quad a-c-b-d stays convex seen along its normal: the flipped pair does not fold.
bool flipKeepsOrientation(const std::vector<Vec3>& p, Index a, Index b, Index c, Index d) {
  const Vec3 old_normal = normalOf(p[a], p[b], p[c]) + normalOf(p[b], p[a], p[d]);
  return normalOf(p[d], p[c], p[a]).dot(old_normal) > 0 && normalOf(p[c], p[d], p[b]).dot(old_normal) > 0;
}


}  // namespace

Index equalizeValences(SurfaceMesh& m, bool keep_delaunay) {
  Index flips = 0;
  const auto& p = m.positions();
  for (Index h = 0; h < m.numHalfedges(); ++h) {
    const Index t = m.twin(h);
    if (h > t || !m.isFlippable(h)) continue;
    const Index a = m.tail(h), b = m.tip(h), c = m.tip(m.next(h)), d = m.tip(m.next(t));
    auto deviation = [&](int da, int db, int dc, int dd) {
      const int va = m.valence(a) + da - targetValence(m, a), vb = m.valence(b) + db - targetValence(m, b);
      const int vc = m.valence(c) + dc - targetValence(m, c), vd = m.valence(d) + dd - targetValence(m, d);
      return va * va + vb * vb + vc * vc + vd * vd;
    };
    if (deviation(-1, -1, 1, 1) >= deviation(0, 0, 0, 0)) continue;
    if (!flipKeepsOrientation(p, a, b, c, d)) continue;
    // The new edge c-d must itself be Delaunay, or a Delaunay sweep would undo the flip.
    if (keep_delaunay && angleAt(p[a], p[c], p[d]) + angleAt(p[b], p[c], p[d]) > constants::kPi) continue;
    flips += m.flip(h);
  }
  return flips;
}

Index flipToDelaunay(SurfaceMesh& m) {
  Index flips = 0;
  const auto& p = m.positions();
  for (Index h = 0; h < m.numHalfedges(); ++h) {
    const Index t = m.twin(h);
    if (h > t || !m.isFlippable(h)) continue;
    const Index a = m.tail(h), b = m.tip(h), c = m.tip(m.next(h)), d = m.tip(m.next(t));
    if (angleAt(p[c], p[a], p[b]) + angleAt(p[d], p[a], p[b]) <= constants::kPi + 1e-12) continue;
    if (!flipKeepsOrientation(p, a, b, c, d)) continue;
    flips += m.flip(h);
  }
  return flips;
}

void smoothTangentially(SurfaceMesh& m, const SurfaceProjector& project, double step) {
  std::vector<Vec3>& p = m.positions();
  std::vector<Vec3> moved = p;
  for (Index v = 0; v < m.numVertices(); ++v) {
    if (m.isBoundaryVertex(v)) continue;
    Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
    Index count = 0;
    Index h = m.outgoing(v);
    do {
      centroid += p[m.tip(h)];
      normal += normalOf(p[v], p[m.tip(h)], p[m.tip(m.next(h))]);
      ++count;
      h = m.rotate(h);
    } while (h != m.outgoing(v));
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
