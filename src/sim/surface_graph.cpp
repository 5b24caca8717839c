#include "sim/surface_graph.hpp"

#include <stdexcept>

#include "mesh/cotan.hpp"

namespace cortex {

std::vector<double> dualCellAreas(const SurfaceMesh& mesh) {
  const auto& x = mesh.positions();
  std::vector<double> area(static_cast<std::size_t>(mesh.numVertices()), 0.0);
  for (Index f = 0; f < mesh.numFaces(); ++f) {
    if (mesh.isDeletedFace(f)) throw std::logic_error("dualCellAreas: the mesh has deleted faces (garbageCollect first)");
    const Tri t = mesh.faceVertices(f);
    const double third = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm() / 6.0;
    for (Index v : t) area[v] += third;
  }
  return area;
}

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
