#include "mesh/dual_cells.hpp"

#include <stdexcept>

namespace cortex {

std::vector<double> dualCellAreas(const SurfaceMesh& mesh) {
  const auto& x = mesh.positions();
  std::vector<double> area(static_cast<std::size_t>(mesh.numVertices()), 0.0);
  for (Index f = 0; f < mesh.numFaces(); ++f) {
    if (mesh.isDeletedFace(f)) throw std::logic_error("dualCellAreas: the mesh has deleted faces (garbageCollect first)");
    const Tri t = mesh.faceVertices(f);
    const double third = triangleArea(x[t[0]], x[t[1]], x[t[2]]) / 3.0;
    for (Index v : t) area[v] += third;
  }
  return area;
}

}  // namespace cortex
