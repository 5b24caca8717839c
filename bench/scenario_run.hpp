// Running a scenario's System through the real loop (no files written) under Google
// Benchmark, and what the benchmarks report of it: wall and simulated time, the time per
// phase the loop counts, reaction events and force evaluations (of the last iteration).
#pragma once

#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>

#include "sim/simulation.hpp"
#include "sim/system.hpp"

namespace cortex::bench {

struct ScenarioRun {
  double simulated = 0.0, wall = 0.0;  // s, over all iterations
  RunCounters counters;
  std::int64_t events = 0, force_evaluations = 0;
};

inline ScenarioRun runScenario(const Config& config, benchmark::State& state) {
  RunObserver quiet;
  ScenarioRun r;
  for (auto _ : state) {
    auto system = std::make_unique<System>(config);
    Simulation sim(*system, config.simulation, config.mechanics, quiet);
    const auto start = std::chrono::steady_clock::now();
    sim.run(true);
    r.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.simulated += config.simulation.end_time;
    r.counters = system->counters;
    r.events = system->chemistry()->events();
    r.force_evaluations = system->forceField().forceEvaluations();
  }
  return r;
}

}  // namespace cortex::bench
