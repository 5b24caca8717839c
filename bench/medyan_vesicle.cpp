// The MEDYAN `vesicle` benchmark of issue 14: examples/medyan_vesicle.toml (a vesicle of
// radius 800 nm in 6^3 compartments with two membrane species binding, dimerizing and
// unbinding, and 81 filaments with linkers, motors and Arp2/3) for 0.2 simulated seconds
// on one thread, through the real loop (no files written). Reports simulated seconds per
// wall second against MEDYAN's 0.04 s in 140 s (2.9e-4 /s; the target is 1000x),
// the time per phase, reaction events and force evaluations. Peak memory is measured
// outside (docs/proteins.md: /usr/bin/time -v on `cortex run`).
#include <benchmark/benchmark.h>

#include "io/config.hpp"
#include "scenario_run.hpp"

namespace cortex {
namespace {

constexpr double kMedyanRate = 0.04 / 140.0;  // simulated s per wall s

void BM_MedyanVesicle(benchmark::State& state) {
  const Config config =
      loadConfig(CORTEX_SOURCE_DIR "/examples/medyan_vesicle.toml", {"simulation.end_time=0.2"});
  const bench::ScenarioRun r = bench::runScenario(config, state);
  const double rate = r.simulated / r.wall;
  state.counters["sim_s_per_wall_s"] = rate;
  state.counters["x_medyan"] = rate / kMedyanRate;
  state.counters["chemistry_s"] = r.counters.chemistry_seconds;
  state.counters["minimization_s"] = r.counters.mechanics_seconds;
  state.counters["remesh_s"] = r.counters.remesh_seconds;
  state.counters["feedback_s"] = r.counters.feedback_seconds;
  state.counters["events"] = static_cast<double>(r.events);
  state.counters["force_evaluations"] = static_cast<double>(r.force_evaluations);
}
BENCHMARK(BM_MedyanVesicle)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
