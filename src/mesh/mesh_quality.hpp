// Quality of a mesh: what the log and summary.json report, and what the loop checks to
// stop a run whose mesh has degenerated.
#pragma once

#include "mesh/surface_mesh.hpp"

namespace cortex {

struct MeshQuality {
  double min_angle_deg = 180.0;     // smallest triangle corner angle
  double max_aspect_ratio = 0.0;    // longest edge / shortest altitude * sqrt(3)/2 (1 = equilateral)
  double min_dihedral_cos = 1.0;    // smallest cosine between the normals of neighbouring triangles
  Index worst_face = -1;            // face with the smallest angle
};

MeshQuality measureQuality(const SurfaceMesh& mesh);

}  // namespace cortex
