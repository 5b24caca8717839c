#include "membrane/regularization_energy.hpp"

#include <cmath>

#include "core/parallel.hpp"
#include "mesh/corner_gather.hpp"

namespace cortex {

double RegularizationEnergy::evaluate(const Evaluation& e) {
  const MeshGeometry& g = membrane_.geometry(e);
  const MeshTopology& topo = membrane_.topology();
  const double k = membrane_.now().k_regularization;
  const double c = 1.0 / (4.0 * std::sqrt(3.0));
  const double* x = e.x + 3 * membrane_.dofOffset();
  const Index nf = topo.numFaces();
  auto edgesOf = [&](Index f) {
    const Tri& t = topo.triangles[f];
    return TriangleEdges(vertexAt(x, t[0]), vertexAt(x, t[1]), vertexAt(x, t[2]));
  };
  const double energy = k * deterministicSum(nf, [&](Index f) {
    const TriangleEdges ed = edgesOf(f);
    return c * (ed.e[0].squaredNorm() + ed.e[1].squaredNorm() + ed.e[2].squaredNorm()) - g.face_area[f];
  });
  double* grad = gradientOf(e);
  if (!grad) return energy;
  corner_gradient_.resize(3 * static_cast<std::size_t>(nf));
  parallelFor(nf, [&](Index f) {
    const TriangleEdges ed = edgesOf(f);
    const Vec3& n = g.face_unit_normal[f];
    for (int p = 0; p < 3; ++p)
      corner_gradient_[3 * f + p] =
          k * (2.0 * c * (ed.e[(p + 1) % 3] - ed.e[(p + 2) % 3]) - 0.5 * n.cross(ed.e[p]));
  });
  gatherCorners(topo, corner_gradient_, grad);
  return energy;
}

}  // namespace cortex
