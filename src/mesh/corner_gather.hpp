// Per-triangle-corner contributions summed into per-vertex gradients.
//
// Force loops compute, for every triangle, one vector per corner (in parallel, no
// conflicts), then each vertex sums the vectors of its own corners (in parallel, fixed
// order): no atomics, and the result does not depend on the thread count.
#pragma once

#include "core/parallel.hpp"
#include "mesh/mesh_topology.hpp"

namespace cortex {

inline void gatherCorners(const MeshTopology& topo, const std::vector<Vec3>& corner_values,
                          double* gradient) {
  parallelFor(topo.numVertices(), [&](Index v) {
    Vec3 sum = Vec3::Zero();
    for (Index c = topo.corner_offsets[v]; c < topo.corner_offsets[v + 1]; ++c)
      sum += corner_values[topo.corner_ids[c]];
    for (int k = 0; k < 3; ++k) gradient[3 * v + k] += sum[k];
  });
}

}  // namespace cortex
