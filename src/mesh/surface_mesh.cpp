#include "mesh/surface_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include "core/error.hpp"

namespace cortex {
namespace {

std::uint64_t edgeKey(Index a, Index b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

void checkTriangles(const TriangleSoup& soup, const std::string& source) {
  const auto n = static_cast<Index>(soup.positions.size());
  if (soup.triangles.empty()) throw InputError(fmt::format("{}: mesh has no triangles", source));
  std::vector<char> used(soup.positions.size(), 0);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Tri& t = soup.triangles[f];
    for (Index v : t) {
      if (v < 0 || v >= n)
        throw InputError(fmt::format("{}: triangle {} refers to vertex {} (mesh has {} vertices)",
                                     source, f, v, n));
      used[v] = 1;
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw InputError(fmt::format("{}: triangle {} repeats a vertex ({} {} {})", source, f, t[0],
                                   t[1], t[2]));
    const Vec3& a = soup.positions[t[0]];
    const Vec3& b = soup.positions[t[1]];
    const Vec3& c = soup.positions[t[2]];
    if (!a.allFinite() || !b.allFinite() || !c.allFinite())
      throw InputError(fmt::format("{}: triangle {} has a non-finite vertex coordinate", source, f));
    const double longest2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(),
                                      (a - c).squaredNorm()});
    // Zero-area triangles have no normal, so curvature and forces are undefined there.
    if ((b - a).cross(c - a).norm() <= 1e-10 * longest2)
      throw InputError(fmt::format("{}: triangle {} (vertices {} {} {}) is degenerate (zero area)",
                                   source, f, t[0], t[1], t[2]));
  }
  for (Index v = 0; v < n; ++v)
    if (!used[v]) throw InputError(fmt::format("{}: vertex {} belongs to no triangle", source, v));
  // Two triangles on the same three vertices enclose nothing (a flat pillow or a
  // duplicate): manifold by counting, but not a surface.
  std::unordered_map<std::uint64_t, std::size_t> seen;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    Tri t = soup.triangles[f];
    std::sort(t.begin(), t.end());
    const std::uint64_t key = (static_cast<std::uint64_t>(t[0]) << 42) ^ (static_cast<std::uint64_t>(t[1]) << 21) ^
                              static_cast<std::uint64_t>(t[2]);
    auto [it, inserted] = seen.emplace(key, f);
    if (!inserted && std::is_permutation(soup.triangles[it->second].begin(), soup.triangles[it->second].end(),
                                         soup.triangles[f].begin()))
      throw InputError(fmt::format("{}: triangles {} and {} use the same three vertices", source, it->second, f));
  }
}

}  // namespace

SurfaceMesh SurfaceMesh::fromSoup(const TriangleSoup& soup, const std::string& source) {
  checkTriangles(soup, source);
  SurfaceMesh m;
  m.positions_ = soup.positions;
  const auto nf = static_cast<Index>(soup.triangles.size());
  const Index ni = 3 * nf;
  m.he_tip_.resize(ni);
  m.he_next_.resize(ni);
  m.he_prev_.resize(ni);
  m.he_face_.resize(ni);
  m.face_he_.resize(nf);

  std::unordered_map<std::uint64_t, Index> directed;
  directed.reserve(2 * ni);
  for (Index f = 0; f < nf; ++f) {
    const Tri& t = soup.triangles[f];
    m.face_he_[f] = 3 * f;
    for (int k = 0; k < 3; ++k) {
      const Index h = 3 * f + k;
      m.he_tip_[h] = t[(k + 1) % 3];
      m.he_next_[h] = 3 * f + (k + 1) % 3;
      m.he_prev_[h] = 3 * f + (k + 2) % 3;
      m.he_face_[h] = f;
      auto [it, inserted] = directed.emplace(edgeKey(t[k], t[(k + 1) % 3]), h);
      if (!inserted)
        throw InputError(fmt::format(
            "{}: edge {}-{} is traversed in the same direction by triangles {} and {}: the mesh "
            "is inconsistently oriented or the edge is shared by more than two triangles",
            source, t[k], t[(k + 1) % 3], it->second / 3, f));
    }
  }

  // Twins; edges with a single triangle get a boundary half-edge.
  m.he_twin_.assign(ni, kNone);
  std::vector<Index> boundary_out(m.positions_.size(), kNone);
  for (Index h = 0; h < ni; ++h) {
    const Index a = m.he_tip_[m.he_prev_[h]];
    const Index b = m.he_tip_[h];
    if (auto it = directed.find(edgeKey(b, a)); it != directed.end()) {
      m.he_twin_[h] = it->second;
      continue;
    }
    const Index hb = static_cast<Index>(m.he_tip_.size());
    m.he_tip_.push_back(a);
    m.he_face_.push_back(kNone);
    m.he_next_.push_back(kNone);
    m.he_prev_.push_back(kNone);
    m.he_twin_.push_back(h);
    m.he_twin_[h] = hb;
    if (boundary_out[b] != kNone)
      throw InputError(fmt::format(
          "{}: vertex {} is non-manifold (two boundary loops pass through it)", source, b));
    boundary_out[b] = hb;
  }
  m.num_boundary_halfedges_ = static_cast<Index>(m.he_tip_.size()) - ni;
  for (Index hb = ni; hb < m.numHalfedges(); ++hb) {
    const Index nxt = boundary_out[m.he_tip_[hb]];
    m.he_next_[hb] = nxt;
    m.he_prev_[nxt] = hb;
  }

  // Each vertex must be one fan: rotating around it reaches all its outgoing half-edges.
  std::vector<Index> out_count(m.positions_.size(), 0);
  m.vertex_out_.assign(m.positions_.size(), kNone);
  for (Index h = 0; h < m.numHalfedges(); ++h) {
    const Index v = m.tail(h);
    ++out_count[v];
    if (m.vertex_out_[v] == kNone) m.vertex_out_[v] = h;
  }
  for (Index v = 0; v < m.numVertices(); ++v) {
    if (boundary_out[v] != kNone) m.vertex_out_[v] = boundary_out[v];
    if (m.valence(v) != out_count[v])
      throw InputError(fmt::format(
          "{}: vertex {} is non-manifold (its triangles form more than one fan)", source, v));
  }
  return m;
}

Index SurfaceMesh::valence(Index v) const {
  Index count = 0;
  // The bound stops a circulation that never closes (a corrupt mesh under validate()).
  for ([[maybe_unused]] const Index h : outgoingHalfedges(v))
    if (++count > numHalfedges()) break;
  return count;
}

Tri SurfaceMesh::faceVertices(Index f) const {
  const Index h = face_he_[f];
  return {tail(h), he_tip_[h], he_tip_[he_next_[h]]};
}

std::vector<Tri> SurfaceMesh::triangles() const {
  std::vector<Tri> tris(face_he_.size());
  for (Index f = 0; f < numFaces(); ++f) tris[f] = faceVertices(f);
  return tris;
}

bool SurfaceMesh::isFlippable(Index h) const {
  const Index t = he_twin_[h];
  if (isBoundaryHalfedge(h) || isBoundaryHalfedge(t)) return false;
  const Index a = tail(h), b = he_tip_[h];
  const Index c = he_tip_[he_next_[h]], d = he_tip_[he_next_[t]];
  if (c == d || valence(a) <= 3 || valence(b) <= 3) return false;
  for (const Index g : outgoingHalfedges(c)) {
    if (he_tip_[g] == d) return false;  // c-d exists already: flipping would duplicate it
  }
  return true;
}

bool SurfaceMesh::flip(Index h) {
  if (!isFlippable(h)) return false;
  const Index t = he_twin_[h];
  const Index hn = he_next_[h], hp = he_prev_[h], tn = he_next_[t], tp = he_prev_[t];
  const Index a = tail(h), b = he_tip_[h];
  const Index c = he_tip_[hn], d = he_tip_[tn];
  const Index f0 = he_face_[h], f1 = he_face_[t];
  auto link = [this](Index x, Index y, Index z) {
    he_next_[x] = y, he_next_[y] = z, he_next_[z] = x;
    he_prev_[y] = x, he_prev_[z] = y, he_prev_[x] = z;
  };
  he_tip_[h] = c;  // h: d -> c, t: c -> d
  he_tip_[t] = d;
  link(h, hp, tn);  // triangle (d, c, a)
  link(t, tp, hn);  // triangle (c, d, b)
  he_face_[tn] = f0;
  he_face_[hn] = f1;
  face_he_[f0] = h;
  face_he_[f1] = t;
  if (vertex_out_[a] == h) vertex_out_[a] = tn;
  if (vertex_out_[b] == t) vertex_out_[b] = hn;
  return true;
}

void SurfaceMesh::validate() const {
  auto fail = [](const std::string& what) { throw std::logic_error("SurfaceMesh: " + what); };
  for (Index h = 0; h < numHalfedges(); ++h) {
    if (he_twin_[he_twin_[h]] != h) fail(fmt::format("twin of twin of {} is not itself", h));
    if (he_twin_[h] == h) fail(fmt::format("half-edge {} is its own twin", h));
    if (he_next_[he_prev_[h]] != h || he_prev_[he_next_[h]] != h)
      fail(fmt::format("next/prev of half-edge {} disagree", h));
    if (tail(he_next_[h]) != he_tip_[h]) fail(fmt::format("half-edge {} does not chain", h));
    if (he_face_[he_next_[h]] != he_face_[h]) fail(fmt::format("face of {} not kept", h));
    if (tail(h) == he_tip_[h]) fail(fmt::format("half-edge {} is a loop", h));
  }
  for (Index f = 0; f < numFaces(); ++f) {
    const Index h = face_he_[f];
    if (he_face_[h] != f || he_next_[he_next_[he_next_[h]]] != h)
      fail(fmt::format("face {} is not a triangle of its half-edges", f));
  }
  std::vector<Index> out_count(positions_.size(), 0);
  std::unordered_map<std::uint64_t, Index> directed;
  for (Index h = 0; h < numHalfedges(); ++h) {
    ++out_count[tail(h)];
    if (!directed.emplace(edgeKey(tail(h), he_tip_[h]), h).second)
      fail(fmt::format("edge {}-{} appears twice", tail(h), he_tip_[h]));
  }
  for (Index v = 0; v < numVertices(); ++v) {
    const Index h = vertex_out_[v];
    if (tail(h) != v) fail(fmt::format("outgoing half-edge of vertex {} starts elsewhere", v));
    if (valence(v) < 3 - isBoundaryVertex(v)) fail(fmt::format("vertex {} has valence {}", v, valence(v)));
    if (valence(v) != out_count[v]) fail(fmt::format("vertex {} is not a single fan", v));
  }
}

}  // namespace cortex
