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
  return driftFactors(graph, h, h, scheme);
}

DriftFactors driftFactors(const SubvolumeGraph& graph, const std::vector<double>& arrive,
                          const std::vector<double>& leave, DriftScheme scheme) {
  DriftFactors out;
  out.factors.resize(static_cast<std::size_t>(graph.numEdges()));
  for (Index i = 0; i < graph.count(); ++i)
    for (Index e = graph.start[i]; e < graph.start[i + 1]; ++e) {
      const Index j = graph.target[e];
      const double x = arrive[j] - leave[i];
      const double reverse = arrive[i] - leave[j];
      if (scheme == DriftScheme::kExponential) {
        out.factors[e] = bernoulli(x);
      } else if (std::max(std::abs(x), std::abs(reverse)) >= 2.0) {  // both ways, so at |x| = 2 not 0 one way and 2 the other
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
