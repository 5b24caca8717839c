#include "mesh/mesh_topology.hpp"

namespace cortex {

MeshTopology MeshTopology::of(const SurfaceMesh& mesh) {
  MeshTopology t;
  const Index n = mesh.numVertices();
  t.triangles = mesh.triangles();
  t.on_boundary.resize(n);
  for (Index v = 0; v < n; ++v) t.on_boundary[v] = mesh.isBoundaryVertex(v) ? 1 : 0;
  t.corner_offsets.assign(n + 1, 0);
  for (const Tri& tri : t.triangles)
    for (Index v : tri) ++t.corner_offsets[v + 1];
  for (Index v = 0; v < n; ++v) t.corner_offsets[v + 1] += t.corner_offsets[v];
  t.corner_ids.resize(t.corner_offsets[n]);
  std::vector<Index> fill(t.corner_offsets.begin(), t.corner_offsets.end() - 1);
  for (Index f = 0; f < t.numFaces(); ++f)
    for (int k = 0; k < 3; ++k) t.corner_ids[fill[t.triangles[f][k]]++] = 3 * f + k;
  return t;
}

}  // namespace cortex
