// Surface hop events per second (issue 14's benchmark, docs/proteins.md): one species
// diffusing between the dual cells of a 10,242-vertex icosphere of radius 2 µm (edges
// ≈ 75 nm, D = 1 µm²/s, ~700 hops/s per copy), 10 copies per vertex, through the
// next-subvolume engine, one advance of 10 ms per iteration (≥ 7·10⁵ events). Beside it
// the 3D engine's figure on the 50³ grid is in bench_chemistry. Target ≥ 5·10⁶ /s.
// BM_SurfaceDiffusionInteracting: the same copies with a weak Gaussian pair attraction
// (h = 0.01 k_BT, σ = 75 nm: μ₀/|C| ≈ −0.04 k_BT), whose hop rates are recomputed
// around both ends after every hop (sim/pair_interaction.hpp): the price of exactness.
// BM_SurfaceDiffusionOnsite: no pair terms, an on-site energy instead (crowded curvature
// sensing's form: arrival energies 0, 0.1, 0.2, ... k_BT per copy already there, rows of
// 20), so only the rates out of and into a hop's two ends are recomputed.
#include <benchmark/benchmark.h>

#include "chem/chemistry_engine.hpp"
#include "mesh/icosphere.hpp"
#include "sim/pair_interaction.hpp"
#include "sim/surface_graph.hpp"

namespace cortex {
namespace {

enum class Energy { kNone, kPair, kOnsite };

void runSurfaceDiffusion(benchmark::State& state, Energy energy) {
  const SurfaceMesh mesh = SurfaceMesh::fromSoup(icosphere(Vec3::Zero(), 2000.0, 5), "icosphere");
  ChemistryModel model;
  model.volumes.size = {1e12};
  model.volumes.start = {0, 0};
  model.surfaces = {"membrane"};
  model.species = {{"P", 1.0e6, 0}};
  auto engine = makeChemistryEngine(EngineKind::kNextSubvolume, model, {0}, 42);
  const auto n = static_cast<std::size_t>(mesh.numVertices());
  const SubvolumeGraph graph = dualCellGraph(mesh).graph;
  engine->setSurface(0, graph, std::vector<Index>(n, 0), std::vector<int>(n, 10));
  if (energy == Energy::kPair)
    engine->setSurfaceInteraction(0, pairInteraction(graph, gaussianPairMoments(0.01, 75.0), std::vector<double>(n, 0.0),
                                                     DriftScheme::kExponential));
  if (energy == Energy::kOnsite) {
    ChemistryEngine::SurfaceInteraction onsite =
        pairInteraction(graph, PairMoments{}, std::vector<double>(n, 0.0), DriftScheme::kExponential);
    onsite.onsite_start = {0};
    for (std::size_t v = 0; v < n; ++v) {
      for (int m = 0; m < 20; ++m) onsite.onsite.push_back(0.1 * m);
      onsite.onsite_start.push_back(static_cast<Index>(onsite.onsite.size()));
    }
    engine->setSurfaceInteraction(0, std::move(onsite));
  }
  const double window = 0.01;
  engine->advance(window);
  const std::int64_t before = engine->events();
  for (auto _ : state) engine->advance(engine->time() + window);
  const double fired = static_cast<double>(engine->events() - before);
  state.counters["vertices"] = static_cast<double>(n);
  state.counters["events_per_s"] = benchmark::Counter(fired, benchmark::Counter::kIsRate);
  state.counters["events_per_advance"] = fired / static_cast<double>(state.iterations());
}

void BM_SurfaceDiffusion(benchmark::State& state) { runSurfaceDiffusion(state, Energy::kNone); }
void BM_SurfaceDiffusionInteracting(benchmark::State& state) { runSurfaceDiffusion(state, Energy::kPair); }
void BM_SurfaceDiffusionOnsite(benchmark::State& state) { runSurfaceDiffusion(state, Energy::kOnsite); }
BENCHMARK(BM_SurfaceDiffusion)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SurfaceDiffusionInteracting)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SurfaceDiffusionOnsite)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
