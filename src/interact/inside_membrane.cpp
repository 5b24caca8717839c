#include "interact/inside_membrane.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "interact/triangle_queries.hpp"

namespace cortex {

double windingNumber(const SurfaceMesh& mesh, const Vec3& p) {
  const auto& x = mesh.positions();
  double sum = 0.0;
  for (Index f = 0; f < mesh.numFaces(); ++f) {
    if (mesh.isDeletedFace(f)) continue;
    const Tri t = mesh.faceVertices(f);
    const Vec3 a = x[t[0]] - p, b = x[t[1]] - p, c = x[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    // tan(Ω/2) = a·(b×c) / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|)
    sum += 2.0 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
  }
  return sum / (4.0 * M_PI);
}

double distanceToMesh(const SurfaceMesh& mesh, const Vec3& p) {
  const auto& x = mesh.positions();
  double best = std::numeric_limits<double>::infinity();
  for (Index f = 0; f < mesh.numFaces(); ++f) {
    if (mesh.isDeletedFace(f)) continue;
    const Tri t = mesh.faceVertices(f);
    best = std::min(best, (closestPointOnTriangle(p, x[t[0]], x[t[1]], x[t[2]]).point - p).norm());
  }
  return best;
}

bool segmentInside(const SurfaceMesh& mesh, const Vec3& a, const Vec3& b, double margin) {
  if (windingNumber(mesh, a) < 0.5) return false;
  const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / margin)));
  for (int i = 0; i <= pieces; ++i)
    if (distanceToMesh(mesh, a + (b - a) * (static_cast<double>(i) / pieces)) < margin) return false;
  return true;
}

}  // namespace cortex
