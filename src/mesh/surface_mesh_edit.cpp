// Connectivity edits of SurfaceMesh that add or remove elements: split, collapse and
// the garbage collection that compacts the arrays afterwards. (flip lives with the
// builder in surface_mesh.cpp: it only relinks.)
#include <algorithm>

#include "mesh/surface_mesh.hpp"

namespace cortex {

Index SurfaceMesh::split(Index h, const Vec3& position) {
  if (isBoundaryHalfedge(h)) h = he_twin_[h];
  const Index t = he_twin_[h];
  const bool boundary = isBoundaryHalfedge(t);
  const Index h1 = he_next_[h], h2 = he_prev_[h];
  const Index a = tail(h), b = he_tip_[h], c = he_tip_[h1];
  const Index f0 = he_face_[h];

  const Index m = numVertices();
  positions_.push_back(position);
  vertex_out_.push_back(kNone);
  auto newHalfedge = [this](Index tip, Index face) {
    he_tip_.push_back(tip);
    he_face_.push_back(face);
    he_next_.push_back(kNone);
    he_prev_.push_back(kNone);
    he_twin_.push_back(kNone);
    return static_cast<Index>(he_tip_.size()) - 1;
  };
  auto newFace = [this](Index first) {
    face_he_.push_back(first);
    return static_cast<Index>(face_he_.size()) - 1;
  };
  auto link = [this](Index x, Index y, Index z) {
    he_next_[x] = y, he_next_[y] = z, he_next_[z] = x;
    he_prev_[y] = x, he_prev_[z] = y, he_prev_[x] = z;
  };
  auto pair = [this](Index x, Index y) { he_twin_[x] = y, he_twin_[y] = x; };

  // Side of h: (a, b, c) becomes (a, m, c) and (m, b, c).
  const Index f2 = newFace(kNone);
  const Index m_to_c = newHalfedge(c, f0), c_to_m = newHalfedge(m, f2), m_to_b = newHalfedge(b, f2);
  he_tip_[h] = m;
  link(h, m_to_c, h2);
  link(m_to_b, h1, c_to_m);
  he_face_[h1] = f2;
  face_he_[f0] = h;
  face_he_[f2] = m_to_b;
  pair(m_to_c, c_to_m);
  pair(t, m_to_b);  // t now runs b -> m
  he_tip_[t] = m;
  vertex_out_[m] = m_to_c;

  const Index m_to_a = newHalfedge(a, kNone);
  pair(h, m_to_a);
  if (boundary) {
    // The boundary loop gains the half-edge m -> a after b -> m.
    const Index after = he_next_[t];
    he_next_[t] = m_to_a, he_prev_[m_to_a] = t;
    he_next_[m_to_a] = after, he_prev_[after] = m_to_a;
    vertex_out_[m] = m_to_a;
    ++num_boundary_halfedges_;
    return m;
  }
  // Side of t: (b, a, d) becomes (b, m, d) and (m, a, d).
  const Index t1 = he_next_[t], t2 = he_prev_[t];
  const Index d = he_tip_[t1];
  const Index f1 = he_face_[t];
  const Index f3 = newFace(m_to_a);
  he_face_[m_to_a] = f3;
  const Index m_to_d = newHalfedge(d, f1), d_to_m = newHalfedge(m, f3);
  link(t, m_to_d, t2);
  link(m_to_a, t1, d_to_m);
  he_face_[t1] = f3;
  face_he_[f1] = t;
  pair(m_to_d, d_to_m);
  return m;
}

bool SurfaceMesh::isCollapsible(Index h) const {
  const Index t = he_twin_[h];
  const Index a = tail(h), b = he_tip_[h];
  if (isBoundaryVertex(a) || isBoundaryHalfedge(h) || isBoundaryHalfedge(t)) return false;
  const Index c = he_tip_[he_next_[h]], d = he_tip_[he_next_[t]];
  if (valence(c) <= 3 || valence(d) <= 3) return false;
  if (isClosed()) {
    Index live = 0;
    for (Index v = 0; v < numVertices() && live <= 4; ++v) live += !isDeletedVertex(v);
    if (live <= 4) return false;
  }
  // Link condition: a and b may share no neighbour but c and d.
  std::vector<Index> around_b;
  for (const Index g : outgoingHalfedges(b)) around_b.push_back(he_tip_[g]);
  for (const Index g : outgoingHalfedges(a)) {
    const Index n = he_tip_[g];
    if (n != c && n != d && n != b && std::find(around_b.begin(), around_b.end(), n) != around_b.end())
      return false;
  }
  return true;
}

bool SurfaceMesh::collapse(Index h) {
  if (!isCollapsible(h)) return false;
  const Index t = he_twin_[h];
  const Index a = tail(h), b = he_tip_[h];
  const Index h1 = he_next_[h], h2 = he_prev_[h], t1 = he_next_[t], t2 = he_prev_[t];
  const Index c = he_tip_[h1], d = he_tip_[t1];
  const Index o1 = he_twin_[h1], o2 = he_twin_[h2], o3 = he_twin_[t1], o4 = he_twin_[t2];

  // Every half-edge arriving at a now arrives at b.
  for (const Index g : outgoingHalfedges(a)) {
    he_tip_[he_twin_[g]] = b;
  }
  // The two triangles go; their outer edges pair up across them.
  he_twin_[o1] = o2, he_twin_[o2] = o1;
  he_twin_[o3] = o4, he_twin_[o4] = o3;
  if (vertex_out_[b] == h1 || vertex_out_[b] == t) vertex_out_[b] = o4;
  if (vertex_out_[c] == h2) vertex_out_[c] = o1;
  if (vertex_out_[d] == t2) vertex_out_[d] = o3;
  for (Index x : {h, h1, h2, t, t1, t2}) he_tip_[x] = kNone;
  face_he_[he_face_[h]] = kNone;
  face_he_[he_face_[t]] = kNone;
  vertex_out_[a] = kNone;
  garbage_ = true;
  return true;
}

std::vector<Index> SurfaceMesh::garbageCollect() {
  std::vector<Index> vmap(positions_.size(), kNone), fmap(face_he_.size(), kNone), hmap(he_tip_.size(), kNone);
  Index nv = 0, nf = 0, nh = 0;
  for (Index v = 0; v < numVertices(); ++v)
    if (!isDeletedVertex(v)) positions_[nv] = positions_[v], vmap[v] = nv++;
  for (Index f = 0; f < numFaces(); ++f)
    if (!isDeletedFace(f)) fmap[f] = nf++;
  for (Index h = 0; h < numHalfedges(); ++h)
    if (!isDeletedHalfedge(h)) hmap[h] = nh++;
  auto remapped = [](const std::vector<Index>& values, const std::vector<Index>& keep,
                     const std::vector<Index>& map) {
    std::vector<Index> out;
    for (std::size_t i = 0; i < values.size(); ++i)
      if (keep[i] != kNone) out.push_back(values[i] == kNone ? kNone : map[values[i]]);
    return out;
  };
  he_next_ = remapped(he_next_, hmap, hmap);
  he_prev_ = remapped(he_prev_, hmap, hmap);
  he_twin_ = remapped(he_twin_, hmap, hmap);
  he_face_ = remapped(he_face_, hmap, fmap);
  he_tip_ = remapped(he_tip_, hmap, vmap);
  vertex_out_ = remapped(vertex_out_, vmap, hmap);
  face_he_ = remapped(face_he_, fmap, hmap);
  positions_.resize(nv);
  garbage_ = false;
  return vmap;
}

}  // namespace cortex
