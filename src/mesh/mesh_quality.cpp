#include "mesh/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.hpp"

namespace cortex {

MeshQuality measureQuality(const SurfaceMesh& m) {
  MeshQuality q;
  const auto& p = m.positions();
  std::vector<Vec3> normal(m.numFaces(), Vec3::Zero());
  double max_cosine = -1.0;
  for (Index f = 0; f < m.numFaces(); ++f) {
    if (m.isDeletedFace(f)) continue;
    const Tri t = m.faceVertices(f);
    const Vec3 n = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]);
    const double twice_area = n.norm();
    if (twice_area > 0) normal[f] = n / twice_area;
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = p[t[(k + 1) % 3]] - p[t[k]], v = p[t[(k + 2) % 3]] - p[t[k]];
      // The smallest angle has the largest cosine; one acos at the end, not one per corner.
      const double cosine = u.dot(v) / (u.norm() * v.norm());
      if (cosine > max_cosine) max_cosine = cosine, q.worst_face = f;
      longest = std::max(longest, u.norm());
    }
    // longest edge / shortest altitude, normalized to 1 for an equilateral triangle
    const double aspect = twice_area > 0 ? longest * longest / twice_area * std::sqrt(3.0) / 2.0
                                         : std::numeric_limits<double>::infinity();
    q.max_aspect_ratio = std::max(q.max_aspect_ratio, aspect);
  }
  q.min_angle_deg = std::acos(std::clamp(max_cosine, -1.0, 1.0)) * 180.0 / constants::kPi;
  for (Index h = 0; h < m.numHalfedges(); ++h) {
    const Index t = m.twin(h);
    if (h > t || m.isDeletedHalfedge(h) || m.isBoundaryHalfedge(h) || m.isBoundaryHalfedge(t)) continue;
    q.min_dihedral_cos = std::min(q.min_dihedral_cos, normal[m.face(h)].dot(normal[m.face(t)]));
  }
  return q;
}

}  // namespace cortex
