// Events per second of the stochastic chemistry engines (issue 4, docs/benchmarks.md).
//
// (a) Diffusion only: one species, D = 1e6 nm^2/s, h = 100 nm (hop rate 100/s per face),
//     8 copies in every compartment (10^6 copies on the 50^3 grid of the issue). The
//     next-subvolume method runs on 10^3, 20^3 and 50^3; the direct method, whose cost
//     per event is linear in the 6 * compartments hop channels, on 10^3 and 50^3.
// (b) A dense network: 1000 random mass-action reactions among 100 species in one
//     500 nm compartment (generator below; a few tens of copies per species).
// Each benchmark iteration is one advance() of a fixed window, so the per-advance cost
// (a fresh waiting time for every compartment) is included. Windows hold >= 10^5 events
// for the next-subvolume method; the direct method gets shorter ones.
#include <benchmark/benchmark.h>

#include <string>

#include "chem/chemistry_engine.hpp"

namespace cortex {
namespace {

ChemistryModel diffusionModel(int n) {
  ChemistryModel m;
  m.volumes = gridGraph(CompartmentGrid{100.0, {n, n, n}});
  m.species.push_back({"A", 1.0e6});
  return m;
}

// Species X0..X99, each with inflow and decay; the rest conversions, bindings,
// dimerizations and exchanges, none of which creates copies, so the network is ergodic.
ChemistryModel denseNetwork(int num_species, int num_reactions) {
  ChemistryModel m;
  std::vector<ReactionDef> reactions;
  for (int s = 0; s < num_species; ++s) m.species.push_back({"X" + std::to_string(s), 0.0});
  RandomStream rng(12345, StreamId::kInitialConditions);
  const auto pick = [&] { return "X" + std::to_string(static_cast<int>(rng.uniform() * num_species)); };
  for (int s = 0; s < num_species; ++s) {
    const std::string x = "X" + std::to_string(s);
    reactions.push_back(parseReaction("-> " + x, 0.5, m.species));  // µM/s: ~38 copies/s
    reactions.push_back(parseReaction(x + " ->", 1.0, m.species));
  }
  while (static_cast<int>(reactions.size()) < num_reactions) {
    // Separate statements: the operands of + are evaluated in unspecified order.
    const double u = rng.uniform();
    const double rate = 0.2 + rng.uniform();
    std::string x[4];
    for (std::string& name : x) name = pick();
    std::string eq;
    if (u < 0.4)
      eq = x[0] + " -> " + x[1];
    else if (u < 0.7)
      eq = x[0] + " + " + x[1] + " -> " + x[2];
    else if (u < 0.8)
      eq = "2 " + x[0] + " -> " + x[1];
    else
      eq = x[0] + " + " + x[1] + " -> " + x[2] + " + " + x[3];
    reactions.push_back(parseReaction(eq, rate, m.species));
  }
  m.addReactions("benchmark", std::move(reactions));
  return m;
}

void run(benchmark::State& state, EngineKind kind, const ChemistryModel& model, const std::vector<int>& copies,
         double window) {
  auto engine = makeChemistryEngine(kind, model, copies, 42);
  engine->advance(window);  // past the initial transient
  const std::int64_t before = engine->events();
  for (auto _ : state) engine->advance(engine->time() + window);
  const double fired = static_cast<double>(engine->events() - before);
  state.counters["events_per_s"] = benchmark::Counter(fired, benchmark::Counter::kIsRate);
  state.counters["events_per_advance"] = fired / static_cast<double>(state.iterations());
}

void BM_Diffusion(benchmark::State& state, EngineKind kind, int n, double window) {
  const ChemistryModel m = diffusionModel(n);
  run(state, kind, m, std::vector<int>(m.volumes.count(), 8), window);
}
BENCHMARK_CAPTURE(BM_Diffusion, nsm_10cubed, EngineKind::kNextSubvolume, 10, 0.05)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Diffusion, nsm_20cubed, EngineKind::kNextSubvolume, 20, 0.01)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Diffusion, nsm_50cubed, EngineKind::kNextSubvolume, 50, 1e-3)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Diffusion, direct_10cubed, EngineKind::kDirect, 10, 2e-3)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Diffusion, direct_50cubed, EngineKind::kDirect, 50, 1e-6)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

void BM_DenseNetwork(benchmark::State& state, EngineKind kind, double window) {
  const ChemistryModel m = denseNetwork(100, 1000);
  run(state, kind, m, std::vector<int>(100, 50), window);
}
BENCHMARK_CAPTURE(BM_DenseNetwork, nsm_1000reactions, EngineKind::kNextSubvolume, 10.0)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DenseNetwork, direct_1000reactions, EngineKind::kDirect, 1.0)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
