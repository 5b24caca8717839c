// Curvature-adaptive target edge lengths (Dunyach, Vanderhaeghe, Barthe & Botsch 2013):
// an edge of length L on a surface of largest principal curvature k deviates from it
// by at most eps when L = sqrt(6 eps / k - 3 eps^2). Flat regions get `flat_size`;
// everything is clamped to [min_size, max_size], then limited so that neighbouring
// targets differ by at most `gradation` times their distance (a smooth transition).
#pragma once

#include <vector>

#include "mesh/surface_mesh.hpp"

namespace cortex {

struct SizingParameters {
  double flat_size = 50.0;   // nm: target where the surface is flat (config mesh_size)
  double min_size = 12.5;    // nm
  double max_size = 100.0;   // nm
  double tolerance = 0.4;    // nm: eps, the largest mesh-to-surface distance wanted
  double gradation = 0.5;    // dL/dx limit between neighbours
};

// Target length for a curvature k (1/nm), before gradation.
double targetEdgeLength(double max_curvature, const SizingParameters& s);
// Per vertex of the (compacted) mesh, from the normal-variation curvature (see .cpp).
std::vector<double> sizingField(const SurfaceMesh& mesh, const SizingParameters& s);

}  // namespace cortex
