#include "membrane/area_energy.hpp"

#include "core/parallel.hpp"
#include "mesh/corner_gather.hpp"

namespace cortex {

double GlobalAreaEnergy::evaluate(const Evaluation& e) {
  const MeshGeometry& g = membrane_.geometry(e);
  const double k = k_, a0 = a0_;
  const double da = g.area - a0;
  if (double* grad = gradientOf(e)) addScaledVertexField(grad, g.area_gradient, k * da / a0);
  return 0.5 * k * da * da / a0;
}

double PerVertexAreaEnergy::evaluate(const Evaluation& e) {
  const MeshGeometry& g = membrane_.geometry(e);
  const MeshTopology& topo = membrane_.topology();
  const double k = k_;
  const Index nv = topo.numVertices();
  coefficient_.resize(nv);
  const double energy = deterministicSum(nv, [&](Index v) {
    const double a0 = membrane_.material().vertex_area0[v] * scale_;
    const double da = g.vertex_area[v] - a0;
    coefficient_[v] = k * da / a0;
    return 0.5 * k * da * da / a0;
  });
  double* grad = gradientOf(e);
  if (!grad) return energy;
  // dA_v/dx_p = 1/3 sum over triangles t of v containing p of dA_t/dx_p.
  const Index nf = topo.numFaces();
  corner_gradient_.resize(3 * static_cast<std::size_t>(nf));
  parallelFor(nf, [&](Index f) {
    const Tri& t = topo.triangles[f];
    const double c = (coefficient_[t[0]] + coefficient_[t[1]] + coefficient_[t[2]]) / 3.0;
    const Vec3 a = vertexAt(e.x + 3 * membrane_.offset(), t[0]);
    const Vec3 b = vertexAt(e.x + 3 * membrane_.offset(), t[1]);
    const Vec3 cc = vertexAt(e.x + 3 * membrane_.offset(), t[2]);
    const TriangleEdges edges(a, b, cc);
    const Vec3 half_normal = 0.5 * c * g.face_unit_normal[f];
    for (int k3 = 0; k3 < 3; ++k3) corner_gradient_[3 * f + k3] = half_normal.cross(edges.e[k3]);
  });
  gatherCorners(topo, corner_gradient_, grad);
  return energy;
}

double TensionEnergy::evaluate(const Evaluation& e) {
  const MeshGeometry& g = membrane_.geometry(e);
  const double gamma = gamma_;
  if (double* grad = gradientOf(e)) addScaledVertexField(grad, g.area_gradient, gamma);
  return gamma * g.area;
}

}  // namespace cortex
