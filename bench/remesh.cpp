// One adaptive remeshing pass on a ~10,000-vertex vesicle, against one full
// minimization of the same membrane (the target: a pass costs < 10% of it), with
// and without species copies to carry along (mesh/copy_carrier.hpp).
//
// Scenario: a sphere of radius 1000 nm (marching tetrahedra + clean-up at 35 nm edges),
// squashed into an oblate shape (z scaled by 0.6) so curvature varies and the sizing
// field is not uniform: what a membrane looks like after a minimization has deformed it.
// Remeshing settings are the config defaults for mesh_size = 35 nm (min 8.75, max 70,
// tolerance mesh_size/120). The minimization is the next window a run would do: L-BFGS
// to 0.5 pN with bending 100 pN·nm, area modulus 400 pN/nm, volume modulus 0.8 pN/nm²
// and reduced volume 0.9, from that squashed shape.
#include <benchmark/benchmark.h>

#include "mech/minimizer.hpp"
#include "mesh/marching_tetrahedra.hpp"
#include "mesh/remesh.hpp"
#include "sim/system.hpp"

namespace cortex {
namespace {

constexpr double kMeshSize = 35.0;  // nm

const TriangleSoup& squashedVesicle() {
  static const TriangleSoup soup = [] {
    TriangleSoup s = meshImplicitSurface(implicitSphere(Vec3::Zero(), 1000.0), kMeshSize);
    for (Vec3& p : s.positions) p.z() *= 0.6;
    return s;
  }();
  return soup;
}

RemeshSettings defaultSettings() {
  RemeshSettings r;
  r.sizing.flat_size = kMeshSize;
  r.sizing.min_size = kMeshSize / 4;
  r.sizing.max_size = 2 * kMeshSize;
  r.sizing.tolerance = kMeshSize / 120;
  return r;
}

void BM_RemeshPass(benchmark::State& state) {
  const SurfaceMesh original = SurfaceMesh::fromSoup(squashedVesicle(), "bench");
  RemeshStats stats;
  for (auto _ : state) {
    state.PauseTiming();
    SurfaceMesh m = original;
    std::vector<char> fixed(m.numVertices(), 0);
    std::vector<int> copies(m.numVertices(), static_cast<int>(state.range(0)));
    std::vector<double> area0(m.numVertices(), 1.0);
    VertexPayload payload{&fixed, {&copies}, {&area0}};
    state.ResumeTiming();
    stats = remesh(m, payload, defaultSettings());
    benchmark::DoNotOptimize(m.positions().data());
  }
  state.counters["vertices"] = original.numVertices();
  state.counters["sweeps"] = static_cast<double>(stats.sweeps);
  state.counters["edits"] = static_cast<double>(stats.splits + stats.collapses + stats.flips);
}
// Copies per vertex of one species: 0 (nothing to carry), 3, 200 (what the carrier costs).
BENCHMARK(BM_RemeshPass)->Arg(0)->Arg(3)->Arg(200)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_FullMinimization(benchmark::State& state) {
  Config config;
  config.source = "benchmark";
  MembraneConfig& m = config.membranes.emplace_back();
  m.name = "v";
  m.shape = "mesh";
  m.soup = squashedVesicle();
  m.mechanics.bending = {Schedule(100.0), Schedule(0.0), CurvatureEstimator::kUnsigned};
  m.mechanics.area.modulus = Schedule(400.0);
  m.mechanics.volume.modulus = Schedule(0.8);
  m.mechanics.volume.reduced_volume = Schedule(0.9);
  MinimizerSettings settings;
  settings.kind = MinimizerKind::kLbfgs;
  settings.force_tolerance = 0.5;
  long evaluations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    System system(config);
    Eigen::VectorXd x = system.coordinates();
    state.ResumeTiming();
    minimize(system.forceField(), x, settings);
    evaluations = system.forceField().forceEvaluations();
  }
  state.counters["force_evaluations"] = static_cast<double>(evaluations);
}
BENCHMARK(BM_FullMinimization)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
