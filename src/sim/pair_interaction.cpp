#include "sim/pair_interaction.hpp"

#include <numbers>

namespace cortex {

PairMoments gaussianPairMoments(double height, double range) {
  const double s2 = range * range;
  return {-std::numbers::pi * height * s2, -std::numbers::pi * height * s2 * s2 / 4.0};
}

PairKernel pairKernel(const SubvolumeGraph& graph, const PairMoments& m) {
  PairKernel out;
  out.self.assign(static_cast<std::size_t>(graph.count()), 0.0);
  out.pair.assign(static_cast<std::size_t>(graph.numEdges()), 0.0);
  // a_jk from each end (|C_j| / l²_jk), averaged with its reverse so K is symmetric to
  // the last bit (the two differ by rounding).
  std::vector<double> a(out.pair.size());
  for (Index j = 0; j < graph.count(); ++j)
    for (Index e = graph.start[j]; e < graph.start[j + 1]; ++e) a[e] = graph.size[j] / graph.hop_length2[e];
  for (Index j = 0; j < graph.count(); ++j) {
    double row = 0.0;
    for (Index e = graph.start[j]; e < graph.start[j + 1]; ++e) {
      const Index k = graph.target[e], back = reverseEdge(graph, j, e);
      const double ajk = 0.5 * (a[e] + (back < 0 ? a[e] : a[back]));
      out.pair[e] = m.mu2 * ajk / (graph.size[j] * graph.size[k]);
      row += ajk;
    }
    out.self[j] = m.mu0 / graph.size[j] - m.mu2 * row / (graph.size[j] * graph.size[j]);
  }
  return out;
}

ChemistryEngine::SurfaceInteraction pairInteraction(const SubvolumeGraph& graph, const PairMoments& m,
                                                    std::vector<double> potential, DriftScheme scheme) {
  PairKernel k = pairKernel(graph, m);
  ChemistryEngine::SurfaceInteraction out;
  out.potential = std::move(potential);
  out.scheme = scheme;
  out.self = std::move(k.self);
  out.pair = std::move(k.pair);
  return out;
}

}  // namespace cortex
