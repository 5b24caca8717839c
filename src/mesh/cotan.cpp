#include "mesh/cotan.hpp"

namespace cortex {

double cotanOpposite(const SurfaceMesh& mesh, Index h) {
  if (mesh.isBoundaryHalfedge(h)) return 0.0;
  const auto& p = mesh.positions();
  const Vec3& apex = p[mesh.tip(mesh.next(h))];
  const Vec3 u = p[mesh.tail(h)] - apex;
  const Vec3 v = p[mesh.tip(h)] - apex;
  return u.dot(v) / u.cross(v).norm();
}

std::vector<double> cotanWeights(const SurfaceMesh& mesh) {
  std::vector<double> w(mesh.numHalfedges());
  for (Index h = 0; h < mesh.numHalfedges(); ++h)
    w[h] = 0.5 * (cotanOpposite(mesh, h) + cotanOpposite(mesh, mesh.twin(h)));
  return w;
}

}  // namespace cortex
