#include "membrane/curvature.hpp"

#include <cmath>

namespace cortex {

std::vector<double> vertexMeanCurvature(const MeshGeometry& g, const MeshTopology& topo,
                                        CurvatureEstimator estimator) {
  std::vector<double> h(topo.numVertices(), 0.0);
  for (Index v = 0; v < topo.numVertices(); ++v)
    if (!topo.on_boundary[v]) {
      const Vec3& ga = g.area_gradient[v];
      const Vec3& gv = g.volume_gradient[v];
      // The unsigned estimator has no sign; report it with the sign of <gA, gV> so that
      // concave regions still show as concave.
      h[v] = std::copysign(meanCurvature(ga, gv, estimator).H, ga.dot(gv));
    }
  return h;
}

}  // namespace cortex
