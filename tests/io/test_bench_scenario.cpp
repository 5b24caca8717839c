// The benchmark's scenario exists twice: as a C++ Config (bench/actomyosin_scenario.hpp,
// what the benchmark builds its System from) and as a TOML file users run. Both must be
// one scenario: the Systems they build run bit-identically.
#include <gtest/gtest.h>

#include "actomyosin_scenario.hpp"
#include "io/config.hpp"
#include "sim/simulation.hpp"

namespace cortex {
namespace {

TEST(BenchScenario, TomlAndCppActomyosinRunIdentically) {
  Config from_file = loadConfig(CORTEX_SOURCE_DIR "/bench/actomyosin_50filaments.toml", {});
  Config in_code = bench::actomyosin50Filaments();
  for (Config* c : {&from_file, &in_code}) c->simulation.end_time = 2.0;
  System a(from_file), b(in_code);
  RunObserver quiet;
  Simulation(a, from_file.simulation, from_file.mechanics, quiet).run(true);
  Simulation(b, in_code.simulation, in_code.mechanics, quiet).run(true);
  ASSERT_GT(a.chemistry()->events(), 10000);
  EXPECT_EQ(a.chemistry()->events(), b.chemistry()->events());
  const SystemState sa = a.state(), sb = b.state();
  EXPECT_EQ(sa.chemistry->copies, sb.chemistry->copies);
  EXPECT_EQ(sa.counters.minimizer_iterations, sb.counters.minimizer_iterations);
  EXPECT_EQ(a.coordinates(), b.coordinates());
  EXPECT_EQ(sa.filaments->linkers.size(), sb.filaments->linkers.size());
  EXPECT_EQ(sa.filaments->motors.size(), sb.filaments->motors.size());
}

}  // namespace
}  // namespace cortex
