// The actomyosin benchmark of docs/benchmarks.md (MEDYAN's 50filaments_motor_linker:
// 20 s simulated in 28.6 s wall and 2.46 GB on this machine class). Runs the scenario
// (actomyosin_scenario.hpp) through the real loop (no files written) and reports
// simulated seconds per wall second, peak memory, and where the time went: chemistry
// (engine incl. filament events), mechanics (force evaluations and the excluded-volume
// neighbour list they rebuild), and the force-dependent rate update after each
// minimization (incl. the search for binding pairs).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include "actomyosin_scenario.hpp"
#include "scenario_run.hpp"

namespace cortex {
namespace {

double peakResidentMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kB on Linux
}

void BM_Actomyosin50Filaments(benchmark::State& state) {
  const Config config = bench::actomyosin50Filaments();
  const bench::ScenarioRun r = bench::runScenario(config, state);
  state.counters["sim_s_per_wall_s"] = r.simulated / r.wall;
  state.counters["peak_MB"] = peakResidentMegabytes();
  state.counters["chemistry_s"] = r.counters.chemistry_seconds;
  state.counters["mechanics_s"] = r.counters.mechanics_seconds;
  state.counters["rate_update_s"] = r.counters.feedback_seconds;
  state.counters["events"] = static_cast<double>(r.events);
  state.counters["force_evaluations"] = static_cast<double>(r.force_evaluations);
}
BENCHMARK(BM_Actomyosin50Filaments)->Unit(benchmark::kSecond)->Iterations(1)->Repetitions(3)->UseRealTime();

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
