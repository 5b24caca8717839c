// The membrane–filament benchmark of docs/benchmarks.md (issue 13, thesis appendix A.6):
// examples/bundle_protrusion.toml (a bundle of N anchored filaments growing into a patch
// under tension, fig. 2.5) with N = 7, 10 and 14 for 2 simulated seconds on one thread,
// through the real loop (no files written). Reports simulated seconds per wall hour, the
// thesis' figure for the same N (N = 7: 16.1 s in 30.4 h; N = 10: 10.4 s in 72 h;
// N = 14: 4.01 s in 72 h) and the time per phase as in its tables A.4-A.6: chemistry,
// minimization (without remeshing), remeshing, feedback (ratchet loads, rates), output
// (none here), plus force evaluations and reaction events.
#include <benchmark/benchmark.h>

#include "io/config.hpp"
#include "scenario_run.hpp"

namespace cortex {
namespace {

// Simulated seconds per wall hour in the thesis (appendix A.6), by bundle size.
double thesisRate(int n) { return n == 7 ? 16.1 / 30.4 : n == 10 ? 10.4 / 72.0 : 4.01 / 72.0; }

void BM_BundleProtrusion(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Config config = loadConfig(CORTEX_SOURCE_DIR "/examples/bundle_protrusion.toml",
                                    {"filaments.0.count=" + std::to_string(n), "simulation.end_time=2.0"});
  const bench::ScenarioRun r = bench::runScenario(config, state);
  const double per_hour = 3600.0 * r.simulated / r.wall;
  state.counters["sim_s_per_wall_h"] = per_hour;
  state.counters["x_thesis"] = per_hour / thesisRate(n);
  state.counters["chemistry_s"] = r.counters.chemistry_seconds;
  state.counters["minimization_s"] = r.counters.mechanics_seconds;
  state.counters["remesh_s"] = r.counters.remesh_seconds;
  state.counters["feedback_s"] = r.counters.feedback_seconds;
  state.counters["events"] = static_cast<double>(r.events);
  state.counters["force_evaluations"] = static_cast<double>(r.force_evaluations);
}
BENCHMARK(BM_BundleProtrusion)->Arg(7)->Arg(10)->Arg(14)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
