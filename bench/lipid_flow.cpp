// The lipid's flow carrying copies over one deformation (mesh/lipid_flow.hpp): what a
// membrane with surface species pays after every relaxation and before every remesh
// within one.
//
// Scenario: a 10,242-vertex sphere (R = 300 nm, ~10 nm edges) whose vertices slide along
// their meridians, θ → π (θ/π)^{1/1.5}: cells near the north pole grow ~2-fold and the
// largest outflow is 21 cells' worth of lipid, a large relaxation step. Copies per
// vertex: 3 and 200 (the potential solve costs the same for both; the transport's
// binomial draws grow with the copies).
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/constants.hpp"
#include "mesh/copy_carrier.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/lipid_flow.hpp"

namespace cortex {
namespace {

void BM_LipidFlow(benchmark::State& state) {
  constexpr double kRadius = 300.0;
  SurfaceMesh moved = SurfaceMesh::fromSoup(icosphere(Vec3::Zero(), kRadius, 5), "bench");
  const std::vector<double> before = dualCellAreas(moved);
  for (Vec3& x : moved.positions()) {
    const double theta = std::acos(std::clamp(x.z() / x.norm(), -1.0, 1.0)), phi = std::atan2(x.y(), x.x());
    const double t = constants::kPi * std::pow(theta / constants::kPi, 1.0 / 1.5);
    x = kRadius * Vec3(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t));
  }
  const std::vector<double> after = dualCellAreas(moved);
  LipidFlowStats stats;
  for (auto _ : state) {
    state.PauseTiming();
    std::vector<int> copies(moved.numVertices(), static_cast<int>(state.range(0)));
    RandomStream random(1, StreamId::kCopyTransport);
    state.ResumeTiming();
    stats = carryWithLipidFlow(moved, before, after, {&copies}, random);
    benchmark::DoNotOptimize(copies.data());
  }
  state.counters["vertices"] = moved.numVertices();
  state.counters["cells_drained"] = static_cast<double>(stats.cells_drained);
  state.counters["largest_outflow"] = stats.largest_outflow;
}
BENCHMARK(BM_LipidFlow)->Arg(3)->Arg(200)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
