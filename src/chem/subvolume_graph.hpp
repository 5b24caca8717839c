// Where copies live and how they move: subvolumes (compartments of the 3D grid, or the
// dual cells of a membrane's vertices) with a size each, joined by directed edges along
// which a copy of a species with diffusion coefficient D hops at rate D / l^2, l^2 the
// edge's squared hop length. On a cubic grid l = h; on a triangle mesh the cotangent
// discretization gives l^2 = 2 |C_i| / (cot a + cot b) (thesis eq. 3.11 with no
// potential). For detailed balance every edge i -> j has its reverse j -> i with
// size_i / l^2_ij = size_j / l^2_ji (a symmetric conductance): then free diffusion is
// stationary with copies proportional to size.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace cortex {

struct SubvolumeGraph {
  std::vector<double> size;         // per subvolume: nm^3 (volume) or nm^2 (surface)
  std::vector<Index> start{0};      // edges of subvolume i: [start[i], start[i+1])
  std::vector<Index> target;        // per directed edge: the subvolume it leads to
  std::vector<double> hop_length2;  // per directed edge: l^2 (nm^2), hop rate D / l^2
  // Non-zero when the subvolumes are an nx x ny x nz lattice numbered x fastest whose
  // edges lead to face neighbours in the order -x, +x, -y, +y, -z, +z (gridGraph): the
  // engine then finds a hop's destination by arithmetic instead of a memory look-up.
  std::array<int, 3> lattice{0, 0, 0};

  Index count() const { return static_cast<Index>(size.size()); }
  Index numEdges() const { return static_cast<Index>(target.size()); }
};

// The edge j -> i that reverses edge e = i -> j (i = `from`), or -1 if there is none.
Index reverseEdge(const SubvolumeGraph& graph, Index from, Index e);

// Throws InputError (prefixed by `what`) unless the arrays are consistent: sizes finite
// and > 0, edges to other existing subvolumes, squared lengths finite and > 0, every
// edge with its reverse, size / l^2 symmetric to 1e-9 relative, and a lattice (if
// declared) whose edges are its face neighbours in face order.
void validate(const SubvolumeGraph& graph, const std::string& what);

}  // namespace cortex
