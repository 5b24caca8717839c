#include "mesh/mesh_quality.hpp"

#include <cmath>
#include <limits>

#include "core/constants.hpp"

namespace cortex {

MeshQuality measureQuality(const MeshTopology& topo, const std::vector<Vec3>& p) {
  MeshQuality q;
  for (Index f = 0; f < topo.numFaces(); ++f) {
    const Tri& t = topo.triangles[f];
    const double twice_area = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm();
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = p[t[(k + 1) % 3]] - p[t[k]], v = p[t[(k + 2) % 3]] - p[t[k]];
      const double angle = std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / constants::kPi;
      if (angle < q.min_angle_deg) q.min_angle_deg = angle, q.worst_face = f;
      longest = std::max(longest, u.norm());
    }
    // aspect = longest edge / shortest altitude, normalized to 1 for an equilateral triangle
    const double aspect = twice_area > 0 ? longest * longest / twice_area * std::sqrt(3.0) / 2.0
                                         : std::numeric_limits<double>::infinity();
    q.max_aspect_ratio = std::max(q.max_aspect_ratio, aspect);
  }
  return q;
}

}  // namespace cortex
