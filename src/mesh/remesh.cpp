#include "mesh/remesh.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/parallel.hpp"

#include "mesh/copy_carrier.hpp"
#include "mesh/mesh_improvement.hpp"
#include "mesh/vertex_normals.hpp"

namespace cortex {
namespace {

constexpr double kSplitAbove = 4.0 / 3.0;    // of the target length (Botsch & Kobbelt)
constexpr double kCollapseBelow = 4.0 / 5.0;
// A triangle normal may turn by at most this much (cosine) in a collapse or relocation:
// more means the edit folds or badly distorts the surface.
constexpr double kMinNormalCosine = 0.5;
constexpr double kConvergedFraction = 0.01;

bool isFixed(const VertexPayload& p, Index v) { return p.fixed && (*p.fixed)[v]; }

Vec3 faceNormal(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

// Midpoint of edge a-b lifted onto the circle through a and b that is tangent to the
// vertex normals: the sagitta s = -1/8 [(b-a).n_a + (a-b).n_b], exact on a sphere.
Vec3 smoothMidpoint(const Vec3& a, const Vec3& b, const Vec3& na, const Vec3& nb) {
  const double sagitta = -0.125 * ((b - a).dot(na) + (a - b).dot(nb));
  const Vec3 n = na + nb;
  const double len = n.norm();
  return 0.5 * (a + b) + (len > 0 ? Vec3(sagitta * n / len) : Vec3::Zero());
}

// True if moving vertex v to `to` keeps every triangle around it (except those also
// containing `skip`) within the allowed normal rotation.
bool keepsOrientation(const SurfaceMesh& m, Index v, const Vec3& to, Index skip) {
  const auto& p = m.positions();
  for (const Index h : m.outgoingHalfedges(v)) {
    if (!m.isBoundaryHalfedge(h)) {
      const Index b = m.tip(h), c = m.tip(m.next(h));
      if (b != skip && c != skip) {
        const Vec3 before = faceNormal(p[v], p[b], p[c]);
        const Vec3 after = faceNormal(to, p[b], p[c]);
        if (after.dot(before) <= kMinNormalCosine * after.norm() * before.norm()) return false;
      }
    }
  }
  return true;
}

double edgeTarget(const std::vector<double>& target, Index a, Index b) { return 0.5 * (target[a] + target[b]); }

// The triangles on either side of half-edge h, with their areas.
std::vector<FaceArea> facesBeside(const SurfaceMesh& m, Index h) {
  std::vector<FaceArea> faces;
  const auto& p = m.positions();
  for (const Index side : {h, m.twin(h)}) {
    if (m.isBoundaryHalfedge(side)) continue;
    const Tri t = m.faceVertices(m.face(side));
    faces.push_back({t, triangleArea(p[t[0]], p[t[1]], p[t[2]])});
  }
  return faces;
}

Index splitLongEdges(SurfaceMesh& m, std::vector<double>& target, VertexPayload& payload, CopyCarrier& carrier) {
  std::vector<Vec3> normals = vertexNormals(m);
  Index splits = 0;
  // Only the edges present at the start: a sweep at most halves an edge, so one bad
  // sizing estimate cannot run away; the next sweep continues if needed.
  const Index existing = m.numHalfedges();
  for (Index h = 0; h < existing; ++h) {
    const Index t = m.twin(h);
    if (h > t) continue;
    const Index a = m.tail(h), b = m.tip(h);
    const Vec3 pa = m.positions()[a], pb = m.positions()[b];
    if ((pb - pa).norm() <= kSplitAbove * edgeTarget(target, a, b)) continue;
    const bool on_boundary = m.isBoundaryHalfedge(h) || m.isBoundaryHalfedge(t);
    const Vec3 x = on_boundary ? Vec3(0.5 * (pa + pb)) : smoothMidpoint(pa, pb, normals[a], normals[b]);
    const std::vector<FaceArea> before = carrier.active() ? facesBeside(m, h) : std::vector<FaceArea>{};
    const Index added = m.split(h, x);
    ++splits;
    normals.push_back((normals[a] + normals[b]).normalized());
    target.push_back(edgeTarget(target, a, b));
    if (payload.fixed) payload.fixed->push_back(isFixed(payload, a) && isFixed(payload, b) && on_boundary);
    for (std::vector<double>* e : payload.extensive) e->push_back(0.0);
    for (std::vector<int>* c : payload.counts) c->push_back(0);
    if (carrier.active()) {
      carrier.addVertex();
      carrier.replaced(before, facesAround(m, added));
    }
  }
  return splits;
}

bool collapseWouldBeHealthy(const SurfaceMesh& m, Index a, Index b, const std::vector<double>& target) {
  const auto& p = m.positions();
  for (const Index h : m.outgoingHalfedges(a)) {
    const Index u = m.tip(h);
    if (u != b && (p[b] - p[u]).norm() > kSplitAbove * edgeTarget(target, b, u)) return false;
  }
  return keepsOrientation(m, a, p[b], b);
}

// The triangles around a once a has merged into b: those not on edge a-b, with b for a.
std::vector<FaceArea> facesAfterCollapse(const SurfaceMesh& m, const std::vector<FaceArea>& around_a, Index b) {
  std::vector<FaceArea> faces;
  const auto& p = m.positions();
  for (FaceArea f : around_a) {
    if (std::find(f.vertices.begin(), f.vertices.end(), b) != f.vertices.end()) continue;
    f.vertices[0] = b;  // facesAround puts the centre first
    f.area = triangleArea(p[b], p[f.vertices[1]], p[f.vertices[2]]);
    faces.push_back(f);
  }
  return faces;
}

Index collapseShortEdges(SurfaceMesh& m, const std::vector<double>& target, VertexPayload& payload,
                         CopyCarrier& carrier) {
  Index collapses = 0;
  for (Index h = 0; h < m.numHalfedges(); ++h) {
    if (m.isDeletedHalfedge(h)) continue;
    const Index a = m.tail(h), b = m.tip(h);
    if (isFixed(payload, a)) continue;
    if ((m.positions()[b] - m.positions()[a]).norm() >= kCollapseBelow * edgeTarget(target, a, b)) continue;
    if (!m.isCollapsible(h) || !collapseWouldBeHealthy(m, a, b, target)) continue;
    const std::vector<FaceArea> before = carrier.active() ? facesAround(m, a) : std::vector<FaceArea>{};
    m.collapse(h);
    ++collapses;
    carrier.replaced(before, facesAfterCollapse(m, before, b));
    for (std::vector<double>* e : payload.extensive) (*e)[b] += (*e)[a], (*e)[a] = 0.0;
  }
  return collapses;
}

template <class T>
void compact(std::vector<T>& values, const std::vector<Index>& map) {
  std::vector<T> out;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (map[i] != kNone) out.push_back(values[i]);
  values.swap(out);
}

void compactAll(SurfaceMesh& m, std::vector<double>& target, VertexPayload& payload) {
  const std::vector<Index> map = m.garbageCollect();
  compact(target, map);
  if (payload.fixed) compact(*payload.fixed, map);
  for (std::vector<int>* c : payload.counts) compact(*c, map);
  for (std::vector<double>* e : payload.extensive) compact(*e, map);
}

void redistributeExtensive(const SurfaceMesh& m, VertexPayload& payload) {
  if (payload.extensive.empty()) return;
  const std::vector<double> area = dualCellAreas(m);
  const double total_area = std::accumulate(area.begin(), area.end(), 0.0);
  for (std::vector<double>* e : payload.extensive) {
    const double total = std::accumulate(e->begin(), e->end(), 0.0);
    for (Index v = 0; v < m.numVertices(); ++v) (*e)[v] = total * area[v] / total_area;
  }
}

// A Jacobi sweep moves every vertex at once. The copies follow the same moves made one
// vertex at a time in index order (so the draws do not depend on the thread count): the
// cells' changes, each move seeing the earlier ones, add up to the sweep's exactly.
void carryThroughMoves(const SurfaceMesh& m, const std::vector<Vec3>& moved, const std::vector<char>& did_move,
                       CopyCarrier& carrier) {
  std::vector<Vec3> p = m.positions();
  auto areasAround = [&](std::vector<FaceArea> faces) {
    for (FaceArea& f : faces) f.area = triangleArea(p[f.vertices[0]], p[f.vertices[1]], p[f.vertices[2]]);
    return faces;
  };
  for (Index v = 0; v < m.numVertices(); ++v) {
    if (!did_move[v]) continue;
    const std::vector<FaceArea> before = areasAround(facesAround(m, v));
    p[v] = moved[v];
    carrier.replaced(before, areasAround(before));
  }
}

}  // namespace

// Moves vertices towards the area-weighted centroid of their 1-ring, within the
// tangent plane, where that does not fold a triangle. All targets are computed from the
// old positions (Jacobi), so vertices are independent and the loop runs in parallel
// with a result that does not depend on the thread count.
Index relocateTangentially(SurfaceMesh& m, const std::vector<char>* fixed, CopyCarrier* carrier) {
  const std::vector<Vec3> normals = vertexNormals(m);
  const auto& p = m.positions();
  std::vector<Vec3> moved = p;
  std::vector<char> did_move(m.numVertices(), 0);
  parallelFor(m.numVertices(), [&](Index v) {
    if (m.isBoundaryVertex(v) || (fixed && (*fixed)[v])) return;
    Vec3 centroid = Vec3::Zero();
    double weight = 0.0;
    for (const Index h : m.outgoingHalfedges(v)) {
      const Index b = m.tip(h), c = m.tip(m.next(h));
      const double area = faceNormal(p[v], p[b], p[c]).norm();
      centroid += area * (p[v] + p[b] + p[c]) / 3.0;
      weight += area;
    }
    if (!(weight > 0)) return;
    Vec3 shift = centroid / weight - p[v];
    shift -= normals[v] * normals[v].dot(shift);
    const Vec3 to = p[v] + shift;
    if (!keepsOrientation(m, v, to, kNone)) return;
    moved[v] = to;
    did_move[v] = 1;
  });
  if (carrier && carrier->active()) carryThroughMoves(m, moved, did_move, *carrier);
  m.positions().swap(moved);
  return static_cast<Index>(std::count(did_move.begin(), did_move.end(), 1));
}

RemeshStats remesh(SurfaceMesh& m, VertexPayload& payload, const RemeshSettings& settings) {
  RemeshStats stats;
  // Sizing comes from the shape as the pass found it; splits and collapses carry it along.
  std::vector<double> target = sizingField(m, settings.sizing);
  CopyCarrier carrier = CopyCarrier::keyedByState(m, payload.counts);
  const FlipObserver carry_through_flip = [&](Index a, Index b, Index c, Index d) {
    const auto& p = m.positions();
    const FaceArea before[2] = {{{a, b, c}, triangleArea(p[a], p[b], p[c])}, {{b, a, d}, triangleArea(p[b], p[a], p[d])}};
    const FaceArea after[2] = {{{c, d, b}, triangleArea(p[c], p[d], p[b])}, {{d, c, a}, triangleArea(p[d], p[c], p[a])}};
    carrier.replaced(before, after);
  };
  const FlipObserver no_observer;
  const FlipObserver& on_flip = carrier.active() ? carry_through_flip : no_observer;
  for (int sweep = 0; sweep < settings.max_sweeps; ++sweep) {
    const Index splits = splitLongEdges(m, target, payload, carrier);
    const Index collapses = collapseShortEdges(m, target, payload, carrier);
    compactAll(m, target, payload);
    carrier.measure(m);
    const Index flips = equalizeValences(m, true, on_flip) + flipToDelaunay(m, on_flip);
    stats.relocations += relocateTangentially(m, payload.fixed, &carrier);
    carrier.measure(m);
    stats.splits += splits, stats.collapses += collapses, stats.flips += flips;
    ++stats.sweeps;
    // Edges near the split/collapse thresholds keep a trickle of edits going; once they
    // touch under 1% of the vertices the mesh is as good as another sweep makes it.
    if (splits + collapses + flips <= kConvergedFraction * m.numVertices()) break;
  }
  redistributeExtensive(m, payload);
  return stats;
}

}  // namespace cortex
