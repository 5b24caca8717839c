// Adaptive remeshing (thesis sec. 2.2.3; Botsch & Kobbelt 2004 with the curvature-
// adaptive sizing of Dunyach et al. 2013): split long edges, collapse short ones, flip
// towards valence 6, relocate vertices tangentially — keeping the shape, refusing any
// edit that would break the manifold or fold a triangle, and carrying per-vertex data
// along with their totals conserved.
#pragma once

#include <vector>

#include "mesh/copy_carrier.hpp"
#include "mesh/sizing_field.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex {

// Per-vertex data that must survive remeshing.
struct VertexPayload {
  std::vector<char>* fixed = nullptr;  // fixed vertices are never moved or removed
  // Integer copies (e.g. surface species): exact totals; they ride the lipid through
  // every edit (copy_carrier.hpp).
  std::vector<std::vector<int>*> counts;
  // Extensive real quantities (e.g. material vertex areas): totals kept, redistributed
  // in proportion to the new vertex areas at the end of the pass.
  std::vector<std::vector<double>*> extensive;
};

struct RemeshSettings {
  SizingParameters sizing;
  int max_sweeps = 5;  // a pass stops earlier once a sweep edits under 1% of the vertices
};

struct RemeshStats {
  std::int64_t splits = 0, collapses = 0, flips = 0, relocations = 0, sweeps = 0;
};

RemeshStats remesh(SurfaceMesh& mesh, VertexPayload& payload, const RemeshSettings& settings);

// One Jacobi sweep moving every vertex (but boundary and `fixed` ones) towards the
// area-weighted centroid of its 1-ring, within its tangent plane, where that folds no
// triangle: evens out the mesh without changing the shape. Copies on the vertices follow
// the cells, if a carrier is given. Returns how many moved.
Index relocateTangentially(SurfaceMesh& mesh, const std::vector<char>* fixed, CopyCarrier* carrier = nullptr);

}  // namespace cortex
