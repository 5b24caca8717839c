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

}  // namespace cortex
