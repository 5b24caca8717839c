#include "membrane/regularization_energy.hpp"

#include <cmath>

#include "core/parallel.hpp"
#include "mesh/corner_gather.hpp"

namespace cortex {

double RegularizationEnergy::evaluate(const Evaluation& e) {
  const MeshGeometry& g = membrane_.geometry(e);
  const MeshTopology& topo = membrane_.topology();
  const double k = k_;
  const double c = 1.0 / (4.0 * std::sqrt(3.0));
  const double* x = e.x + 3 * membrane_.offset();
  const Index nf = topo.numFaces();
  const double mean_area = g.area / nf;
  auto edgesOf = [&](Index f) {
    const Tri& t = topo.triangles[f];
    return TriangleEdges(vertexAt(x, t[0]), vertexAt(x, t[1]), vertexAt(x, t[2]));
  };
  auto sumOfSquares = [](const TriangleEdges& ed) {
    return ed.e[0].squaredNorm() + ed.e[1].squaredNorm() + ed.e[2].squaredNorm();
  };
  const double energy = k * deterministicSum(nf, [&](Index f) {
    const double r = g.face_area[f] / mean_area - 1.0;
    return c * sumOfSquares(edgesOf(f)) / g.face_area[f] - 1.0 + r * r;
  });
  double* grad = gradientOf(e);
  if (!grad) return energy;
  // Shape: dq/dx_p = c [2 (e_{p+1} - e_{p+2}) / A - S / A^2 dA/dx_p], dA/dx_p = 1/2 n x e_p.
  // Size: d(r^2)/dx_p = 2 r [dA_t/dx_p / Ā - A_t / Ā^2 dĀ/dx_p] with dĀ/dx = (dA/dx) / F;
  // the dĀ part sums over all triangles into one multiple of the area gradient.
  const double size_coupling = deterministicSum(nf, [&](Index f) {
    return (g.face_area[f] / mean_area - 1.0) * g.face_area[f];
  }) * 2.0 / (nf * mean_area * mean_area);
  corner_gradient_.resize(3 * static_cast<std::size_t>(nf));
  parallelFor(nf, [&](Index f) {
    const TriangleEdges ed = edgesOf(f);
    const Vec3& n = g.face_unit_normal[f];
    const double a = g.face_area[f];
    const double area_factor = -c * sumOfSquares(ed) / (a * a) + 2.0 * (a / mean_area - 1.0) / mean_area;
    for (int p = 0; p < 3; ++p)
      corner_gradient_[3 * f + p] =
          k * (2.0 * c * (ed.e[(p + 1) % 3] - ed.e[(p + 2) % 3]) / a + 0.5 * area_factor * n.cross(ed.e[p]));
  });
  gatherCorners(topo, corner_gradient_, grad);
  addScaledVertexField(grad, g.area_gradient, -k * size_coupling);
  return energy;
}

}  // namespace cortex
