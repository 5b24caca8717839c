// Basic numeric types shared by every folder.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

namespace cortex {

using Vec3 = Eigen::Vector3d;
using Index = std::int32_t;  // vertex/face/halfedge index; meshes stay far below 2^31
using Tri = std::array<Index, 3>;

// Positions as one array x0 y0 z0 x1 ..., the layout energy terms, minimizers and files use.
inline std::vector<double> flatCoordinates(const std::vector<Vec3>& p) {
  std::vector<double> x;
  x.reserve(3 * p.size());
  for (const Vec3& v : p) x.insert(x.end(), {v.x(), v.y(), v.z()});
  return x;
}

}  // namespace cortex
