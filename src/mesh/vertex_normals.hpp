// Per-vertex unit normals (area-weighted face normals) and curvature magnitudes from
// the 1-ring, for the remesher. The energies use their own estimators (membrane/).
#pragma once

#include <vector>

#include "mesh/surface_mesh.hpp"

namespace cortex {

struct VertexCurvature {
  Vec3 normal;        // unit, area-weighted average of the face normals
  double area;        // one third of the 1-ring area
  double mean;        // |H| from the cotan Laplacian: |dA/dx| / (2 A_v)
  double gaussian;    // K = angle defect / A_v (0 on boundary vertices)
  double maxPrincipal() const;  // |H| + sqrt(max(H^2 - K, 0))
};

std::vector<Vec3> vertexNormals(const SurfaceMesh& mesh);
VertexCurvature vertexCurvature(const SurfaceMesh& mesh, Index v);

}  // namespace cortex
