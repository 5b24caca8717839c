#include "mesh/vertex_normals.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace cortex {

double VertexCurvature::maxPrincipal() const { return mean + std::sqrt(std::max(mean * mean - gaussian, 0.0)); }

std::vector<Vec3> vertexNormals(const SurfaceMesh& m) {
  std::vector<Vec3> normals(m.numVertices(), Vec3::Zero());
  const auto& p = m.positions();
  for (Index f = 0; f < m.numFaces(); ++f) {
    if (m.isDeletedFace(f)) continue;
    const Tri t = m.faceVertices(f);
    const Vec3 n = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]);
    for (Index v : t) normals[v] += n;
  }
  for (Vec3& n : normals) {
    const double len = n.norm();
    if (len > 0) n /= len;
  }
  return normals;
}

VertexCurvature vertexCurvature(const SurfaceMesh& m, Index v) {
  const auto& p = m.positions();
  Vec3 area_gradient = Vec3::Zero(), normal = Vec3::Zero();
  double area = 0.0, angles = 0.0;
  for (const Index h : m.outgoingHalfedges(v)) {
    if (!m.isBoundaryHalfedge(h)) {
      const Vec3& a = p[v];
      const Vec3& b = p[m.tip(h)];
      const Vec3& c = p[m.tip(m.next(h))];
      const Vec3 n = (b - a).cross(c - a);
      const double len = n.norm();
      if (len > 0) {
        area += len / 6.0;
        area_gradient += 0.5 * (n / len).cross(c - b);
        normal += n;
        angles += std::atan2(len, (b - a).dot(c - a));
      }
    }
  }
  VertexCurvature k;
  k.normal = normal.norm() > 0 ? Vec3(normal.normalized()) : Vec3::Zero();
  k.area = area;
  k.mean = area > 0 ? area_gradient.norm() / (2.0 * area) : 0.0;
  k.gaussian = m.isBoundaryVertex(v) || area <= 0 ? 0.0 : (2.0 * constants::kPi - angles) / area;
  return k;
}

}  // namespace cortex
