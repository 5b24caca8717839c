// The dual cells of a membrane's vertices as the subvolumes of its surface species
// (thesis section 3.2, eqs. 3.8–3.11, without a potential): cell j has the area |C_j|,
// one third of the areas of the triangles around vertex j, and a copy hops from vertex i
// to a neighbour j at rate
//   D (cot α_ij + cot β_ij) / (2 |C_i|)
// with α_ij, β_ij the angles opposite edge ij (one of them on a boundary edge): the
// cotangent Laplacian, so that on a flat mesh the walk has no drift and its mean squared
// displacement grows as 4Dt. In SubvolumeGraph terms the squared hop length is
// l²_ij = 2 |C_i| / (cot α_ij + cot β_ij), and |C_i| / l²_ij = (cot α + cot β)/2 is the
// same both ways (detailed balance: copies stationary in proportion to |C_j|).
//
// An edge whose cotangent sum is not positive (α + β ≥ π, an edge that is not locally
// Delaunay) would have a negative rate; it is left out both ways (rate 0 in each
// direction), the symmetric clipping that keeps detailed balance (docs/proteins.md).
#pragma once

#include "chem/subvolume_graph.hpp"
#include "mesh/dual_cells.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex {

struct DualCellGraph {
  SubvolumeGraph graph;  // subvolume j = vertex j
  Index clipped_edges = 0;  // edges left out because their cotangent sum is < 0 (a sum of 0 is a rate of 0)
};

// `mesh` must be compacted (no deleted elements, as after garbageCollect()).
DualCellGraph dualCellGraph(const SurfaceMesh& mesh);

}  // namespace cortex
