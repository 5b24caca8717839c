// A plain list of positions and triangles: what generators and file readers produce
// before the half-edge mesh is built (and validated) from it.
#pragma once

#include <vector>

#include "core/types.hpp"

namespace cortex {

struct TriangleSoup {
  std::vector<Vec3> positions;
  std::vector<Tri> triangles;  // counter-clockwise seen from outside (normal points outwards)
};

}  // namespace cortex
