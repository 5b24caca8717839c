// The dual cells of a triangle mesh's vertices: cell j is a third of the area of the
// triangles around vertex j, so the cells tile the surface exactly. Copies of membrane
// species live on them (sim/surface_graph.hpp, mesh/copy_carrier.hpp).
#pragma once

#include <vector>

#include "mesh/surface_mesh.hpp"

namespace cortex {

inline double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

// The dual-cell areas |C_j| (nm^2). `mesh` must be compacted (no deleted elements, as
// after garbageCollect()).
std::vector<double> dualCellAreas(const SurfaceMesh& mesh);

}  // namespace cortex
