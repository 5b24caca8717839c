// Triangle quality of a mesh: what the log and summary.json report, and what the loop
// checks to stop a run whose mesh has degenerated.
#pragma once

#include "core/types.hpp"
#include "mesh/mesh_topology.hpp"

namespace cortex {

struct MeshQuality {
  double min_angle_deg = 180.0;  // smallest triangle corner angle
  double max_aspect_ratio = 0.0; // longest edge / shortest altitude * sqrt(3)/2 (1 = equilateral)
  Index worst_face = -1;         // face with the smallest angle
};

MeshQuality measureQuality(const MeshTopology& topo, const std::vector<Vec3>& positions);

}  // namespace cortex
