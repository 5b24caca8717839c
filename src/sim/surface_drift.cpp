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

namespace {

// x / (eˣ − 1), with its limit 1 at x = 0 (expm1 keeps it accurate for small |x|).
double bernoulli(double x) { return std::abs(x) < 1e-12 ? 1.0 - 0.5 * x : x / std::expm1(x); }

}  // namespace

DriftFactors driftFactors(const SubvolumeGraph& graph, const std::vector<double>& h, DriftScheme scheme) {
  DriftFactors out;
  out.factors.resize(static_cast<std::size_t>(graph.numEdges()));
  for (Index i = 0; i < graph.count(); ++i)
    for (Index e = graph.start[i]; e < graph.start[i + 1]; ++e) {
      const double x = h[graph.target[e]] - h[i];
      if (scheme == DriftScheme::kExponential) {
        out.factors[e] = bernoulli(x);
      } else if (std::abs(x) >= 2.0) {  // at |x| = 2 one way would be 0, the other 2
        out.factors[e] = 0.0;
        ++out.closed_edges;  // counted from both ends
      } else {
        out.factors[e] = 1.0 - 0.5 * x;
      }
    }
  out.closed_edges /= 2;
  return out;
}

}  // namespace cortex
