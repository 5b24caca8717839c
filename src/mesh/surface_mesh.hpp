// Half-edge surface mesh: connectivity only, plus the vertex positions it carries.
//
// Every triangle owns three half-edges (3f, 3f+1, 3f+2), each going tail -> tip,
// counter-clockwise seen from outside. Edges on an open boundary get a twin half-edge
// with face() == kNone, linked into boundary loops. Handles are plain indices; the
// remesher (which edits connectivity) keeps them compact and reports the renumbering.
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"
#include "mesh/triangle_soup.hpp"

namespace cortex {

inline constexpr Index kNone = -1;

class SurfaceMesh {
 public:
  // Builds and validates the mesh: every edge shared by at most two consistently
  // oriented triangles, every vertex a single fan, no repeated or unused vertex, no
  // zero-area triangle. Throws InputError naming `source` on the first violation.
  static SurfaceMesh fromSoup(const TriangleSoup& soup, const std::string& source);

  // Counts include elements deleted by collapse() until garbageCollect().
  Index numVertices() const { return static_cast<Index>(positions_.size()); }
  Index numFaces() const { return static_cast<Index>(face_he_.size()); }
  Index numHalfedges() const { return static_cast<Index>(he_tip_.size()); }
  Index numEdges() const { return numHalfedges() / 2; }

  Index tip(Index h) const { return he_tip_[h]; }
  Index tail(Index h) const { return he_tip_[he_twin_[h]]; }
  Index next(Index h) const { return he_next_[h]; }
  Index prev(Index h) const { return he_prev_[h]; }
  Index twin(Index h) const { return he_twin_[h]; }
  Index face(Index h) const { return he_face_[h]; }
  bool isBoundaryHalfedge(Index h) const { return he_face_[h] == kNone; }

  // An outgoing half-edge of v; the boundary one when v lies on a boundary.
  Index outgoing(Index v) const { return vertex_out_[v]; }
  bool isBoundaryVertex(Index v) const { return isBoundaryHalfedge(vertex_out_[v]); }
  // Next outgoing half-edge of the same vertex, turning around it.
  Index rotate(Index h) const { return he_twin_[he_prev_[h]]; }
  // The outgoing half-edges of v, from outgoing(v) turning around it with rotate():
  //   for (Index h : mesh.outgoingHalfedges(v)) ...
  // Reads only twin and prev links, so it may be used while tips are rewritten.
  class Circulator {
   public:
    Circulator(const SurfaceMesh& mesh, Index start, bool done) : mesh_(&mesh), h_(start), start_(start), done_(done) {}
    Index operator*() const { return h_; }
    Circulator& operator++() {
      h_ = mesh_->rotate(h_);
      done_ = h_ == start_;
      return *this;
    }
    bool operator!=(const Circulator& other) const { return done_ != other.done_; }

   private:
    const SurfaceMesh* mesh_;
    Index h_, start_;
    bool done_;
  };
  struct HalfedgeRing {
    Circulator first, last;
    Circulator begin() const { return first; }
    Circulator end() const { return last; }
  };
  HalfedgeRing outgoingHalfedges(Index v) const {
    return {Circulator(*this, vertex_out_[v], false), Circulator(*this, vertex_out_[v], true)};
  }
  Index valence(Index v) const;

  Index faceHalfedge(Index f) const { return face_he_[f]; }
  Tri faceVertices(Index f) const;
  std::vector<Tri> triangles() const;

  bool isClosed() const { return num_boundary_halfedges_ == 0; }
  Index eulerCharacteristic() const { return numVertices() - numEdges() + numFaces(); }

  const std::vector<Vec3>& positions() const { return positions_; }
  std::vector<Vec3>& positions() { return positions_; }

  // Edge flip: the interior edge of half-edge h, shared by triangles (a,b,c) and (b,a,d),
  // becomes edge c-d. Refuses (returns false, mesh unchanged) on a boundary edge, when c-d
  // is already an edge, or when a or b would drop below valence 3. Geometry is the
  // caller's business. Handles stay valid: the same half-edges and faces are reused.
  bool flip(Index h);
  bool isFlippable(Index h) const;

  // Edge split: a new vertex at `position` splits the edge of h and each triangle on it
  // in two. Returns the new vertex. Works on boundary edges (the new vertex is then a
  // boundary vertex). Never refuses.
  Index split(Index h, const Vec3& position);

  // Edge collapse: the tail a of h merges into its tip b (b keeps its position; move it
  // afterwards if wanted), removing the one or two triangles on the edge. Refuses
  // (returns false, mesh unchanged) when a is a boundary vertex, when the edge's two
  // ends share a neighbour other than the edge's opposite vertices (the link condition:
  // the result would not be a manifold), when an opposite vertex would drop below
  // valence 3, or when a closed mesh would shrink below a tetrahedron. Removed elements
  // are marked (isDeleted*) until garbageCollect().
  bool collapse(Index h);
  bool isCollapsible(Index h) const;

  bool isDeletedVertex(Index v) const { return vertex_out_[v] == kNone; }
  bool isDeletedFace(Index f) const { return face_he_[f] == kNone; }
  bool isDeletedHalfedge(Index h) const { return he_tip_[h] == kNone; }
  bool hasGarbage() const { return garbage_; }
  // Compacts the arrays after collapses. Returns old vertex index -> new index (kNone
  // for removed vertices) so per-vertex data can follow.
  std::vector<Index> garbageCollect();

  // Checks every connectivity invariant (on a compacted mesh: after garbageCollect());
  // throws std::logic_error on the first broken one.
  // Cheap enough for tests and after every edit in debug builds.
  void validate() const;

 private:
  std::vector<Vec3> positions_;
  std::vector<Index> he_tip_, he_next_, he_prev_, he_twin_, he_face_;
  std::vector<Index> vertex_out_, face_he_;
  Index num_boundary_halfedges_ = 0;
  bool garbage_ = false;
};

}  // namespace cortex
