#include "sim/surface_drift.hpp"

#include <cmath>

namespace cortex {

double surfacePotential(const SurfacePotentialConfig& p, const Vec3& x) {
  const double u = x[p.axis] - p.center;
  switch (p.kind) {
    case SurfacePotentialConfig::Kind::kGaussianStripe:
      return p.height * std::exp(-0.5 * u * u / (p.width * p.width));
    case SurfacePotentialConfig::Kind::kRamp:
      return p.slope * u;
  }
  return 0.0;
}

DriftFactors driftFactors(const SubvolumeGraph& graph, const std::vector<double>& h, DriftScheme scheme) {
  DriftFactors out;
  out.factors.resize(static_cast<std::size_t>(graph.numEdges()));
  for (Index i = 0; i < graph.count(); ++i)
    for (Index e = graph.start[i]; e < graph.start[i + 1]; ++e) {
      const double x = h[graph.target[e]] - h[i];
      if (scheme == DriftScheme::kExponential) {
        out.factors[e] = exponentialDrift(x);
      } else {
        out.factors[e] = linearDrift(x, -x);
        out.closed_edges += out.factors[e] == 0.0;  // counted from both ends
      }
    }
  out.closed_edges /= 2;
  return out;
}

}  // namespace cortex
