// The actomyosin benchmark of docs/benchmarks.md (MEDYAN's 50filaments_motor_linker:
// 20 s simulated in 28.6 s wall and 2.46 GB on this machine class). Runs the scenario
// (actomyosin_scenario.hpp) through the real loop (no files written) and reports
// simulated seconds per wall second, peak memory, and where the time went: chemistry
// (engine incl. filament events), mechanics (force evaluations and the excluded-volume
// neighbour list they rebuild), and the force-dependent rate update after each
// minimization (incl. the search for binding pairs).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>

#include "actomyosin_scenario.hpp"
#include "sim/simulation.hpp"

namespace cortex {
namespace {

double peakResidentMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kB on Linux
}

void BM_Actomyosin50Filaments(benchmark::State& state) {
  const Config config = bench::actomyosin50Filaments();
  RunObserver quiet;
  double simulated = 0.0, wall = 0.0;
  RunCounters counters;
  std::int64_t events = 0, evaluations = 0;
  for (auto _ : state) {
    auto system = std::make_unique<System>(config);
    Simulation sim(*system, config.simulation, config.mechanics, quiet);
    const auto start = std::chrono::steady_clock::now();
    sim.run(true);
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    simulated += config.simulation.end_time;
    counters = system->counters;
    events = system->chemistry()->events();
    evaluations = system->forceField().forceEvaluations();
  }
  state.counters["sim_s_per_wall_s"] = simulated / wall;
  state.counters["peak_MB"] = peakResidentMegabytes();
  state.counters["chemistry_s"] = counters.chemistry_seconds;
  state.counters["mechanics_s"] = counters.mechanics_seconds;
  state.counters["rate_update_s"] = counters.feedback_seconds;
  state.counters["events"] = static_cast<double>(events);
  state.counters["force_evaluations"] = static_cast<double>(evaluations);
}
BENCHMARK(BM_Actomyosin50Filaments)->Unit(benchmark::kSecond)->Iterations(1)->Repetitions(3)->UseRealTime();

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
