#include "sim/surface_graph.hpp"

#include "mesh/cotan.hpp"

namespace cortex {

DualCellGraph dualCellGraph(const SurfaceMesh& mesh) {
  const Index n = mesh.numVertices();
  DualCellGraph out;
  SubvolumeGraph& g = out.graph;
  g.size = dualCellAreas(mesh);
  g.start.clear();
  g.start.push_back(0);
  for (Index v = 0; v < n; ++v) {
    for (Index h : mesh.outgoingHalfedges(v)) {
      const double cot_sum = cotanOpposite(mesh, h) + cotanOpposite(mesh, mesh.twin(h));
      if (cot_sum <= 0.0) {  // rate ≤ 0: no edge either way
        if (cot_sum < 0.0) ++out.clipped_edges;  // counted from both ends
        continue;
      }
      g.target.push_back(mesh.tip(h));
      g.hop_length2.push_back(2.0 * g.size[v] / cot_sum);
    }
    g.start.push_back(static_cast<Index>(g.target.size()));
  }
  out.clipped_edges /= 2;
  return out;
}

}  // namespace cortex
