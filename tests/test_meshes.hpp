// Meshes shared by the tests: spheres and patches, optionally randomly perturbed.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>

#include "mesh/icosphere.hpp"
#include "mesh/planar_patch.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex::testing {

inline void perturb(TriangleSoup& soup, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (Vec3& p : soup.positions) p += Vec3(u(rng), u(rng), u(rng));
}

inline SurfaceMesh sphereMesh(double radius, int subdivisions, double perturbation = 0.0,
                              const Vec3& center = Vec3(0, 0, 0)) {
  TriangleSoup soup = icosphere(center, radius, subdivisions);
  if (perturbation > 0.0) perturb(soup, perturbation, 7);
  return SurfaceMesh::fromSoup(soup, "test sphere");
}

inline SurfaceMesh patchMesh(double size, double edge, double perturbation = 0.0) {
  TriangleSoup soup = planarPatch(Vec3(0, 0, 0), size, size, edge);
  if (perturbation > 0.0) perturb(soup, perturbation, 11);
  return SurfaceMesh::fromSoup(soup, "test patch");
}

// A 200 nm patch of 100 nm edges whose interior vertices are moved off the lattice: a
// small irregular mesh (cells of unequal sizes) for tests that enumerate its states.
inline SurfaceMesh irregularSmallPatch() {
  SurfaceMesh mesh = patchMesh(200.0, 100.0);
  for (Index v = 0; v < mesh.numVertices(); ++v)
    if (!mesh.isBoundaryVertex(v)) mesh.positions()[v] += Vec3(23.0, -14.0, 0.0);
  return mesh;
}

// Largest |h_v − mean of h over v's neighbours| relative to the mean |h|: how far a
// per-vertex field (mean curvature) is from smooth. A relaxed smooth shape reads a few
// percent; curvature hot spots read tens of percent or more.
inline double curvatureRoughness(const SurfaceMesh& mesh, const std::vector<double>& h) {
  double mean_abs = 0.0, worst = 0.0;
  for (double x : h) mean_abs += std::abs(x);
  mean_abs /= static_cast<double>(h.size());
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    double ring = 0.0;
    int k = 0;
    for (Index e : mesh.outgoingHalfedges(v)) ring += h[static_cast<std::size_t>(mesh.tip(e))], ++k;
    worst = std::max(worst, std::abs(h[static_cast<std::size_t>(v)] - ring / k));
  }
  return worst / mean_abs;
}

}  // namespace cortex::testing
