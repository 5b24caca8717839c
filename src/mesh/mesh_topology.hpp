// Flat connectivity for the force loops: the triangle list and, per vertex, the
// triangle corners it owns. Built from the half-edge mesh whenever connectivity changes.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex {

struct MeshTopology {
  std::vector<Tri> triangles;
  // Corners of vertex v are corner_ids[corner_offsets[v] .. corner_offsets[v+1]),
  // each encoded 3*face + k where triangles[face][k] == v.
  std::vector<Index> corner_offsets;
  std::vector<Index> corner_ids;
  std::vector<char> on_boundary;  // per vertex

  static MeshTopology of(const SurfaceMesh& mesh);
  Index numVertices() const { return static_cast<Index>(on_boundary.size()); }
  Index numFaces() const { return static_cast<Index>(triangles.size()); }
};

}  // namespace cortex
