// A run that fails midway (a diverging or non-finite energy): exit code 1, a message saying
// what and when, and the last good snapshot and checkpoint kept (README, exit codes).
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "app/cli_helpers.hpp"
#include "app/snapshots.hpp"
#include "core/error.hpp"
#include "io/config.hpp"
#include "sim/simulation.hpp"
#include "sim/system.hpp"
#include "test_text.hpp"

namespace cortex::cli_test {
namespace {

using cortex::testing::countOccurrences;

// A membrane whose tension turns negative at t = 0.11 s against an area penalty so weak
// (1e-14 pN/nm) that the energy's minimum lies at a radius of ~4e9 nm: out of reach, as
// if unbounded (a negative tension with no area term at all, truly unbounded, is refused
// by the config reader). max_step is raised so the minimizer's runaway guard (a
// coordinate beyond 1e9 nm, mech/minimizer.cpp) is reached within a few iterations; see
// UnboundedEnergyWithDefaultStepFails for the default step.
std::string divergingConfig(const std::string& mechanics_extra) {
  return R"([simulation]
seed = 1
end_time = 0.3
chemistry_window = 0.02
snapshot_interval = 0.04

[mechanics]
minimizer = "lbfgs"
force_tolerance = 0.5
)" + mechanics_extra + R"(

[[membrane]]
name = "vesicle"
shape = "sphere"
mesher = "icosphere"
radius = 200.0
mesh_size = 40.0
bending_modulus = 1.0
area_model = "global"
area_modulus = 1.0e-14
tension = [[0.0, 0.0], [0.1, 0.0], [0.11, -5.0]]
)";
}

TEST(RunFailure, KeepsLastGoodSnapshotAndCheckpoint) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), divergingConfig("max_step = 1.0e7"));
  const fs::path out = dir / "out";
  RunResult r = runConfig(config, out, {}, dir.path());
  ASSERT_EQ(r.exit_code, 1) << describe(r);
  EXPECT_FALSE(r.err.empty()) << describe(r);
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << describe(r);

  // The snapshots written before the failure (t = 0, 0.04, 0.08) are intact.
  ASSERT_TRUE(fs::exists(out / "trajectory.h5"));
  const std::vector<Snapshot> snaps = readSnapshots(out / "trajectory.h5");
  ASSERT_GE(snaps.size(), 2u);
  EXPECT_EQ(snaps[0].time, 0.0);
  for (const Snapshot& s : snaps) {
    EXPECT_LT(s.time, 0.11 + 0.02) << s.group;  // nothing from the diverged windows
    for (double x : s.vertices) ASSERT_TRUE(std::isfinite(x) && std::abs(x) < 1e4) << s.group;
  }
  EXPECT_EQ(countOccurrences(readFile(out / "trajectory.xdmf"), "<Time "), snaps.size());

  // The checkpoint is the last good state, and a run can continue from it with the
  // offending parameter corrected.
  ASSERT_TRUE(fs::exists(out / "checkpoint.h5"));
  {
    const h5::File cp = h5::File::openReadOnly(out / "checkpoint.h5");
    EXPECT_DOUBLE_EQ(cp.attributeDouble("/run", "time"), snaps.back().time);
  }
  r = runCortex({"run", "--resume", out.string(), "--set", "membrane.0.tension=0.0", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_DOUBLE_EQ(readJson(out / "summary.json")["time"].get<double>(), 0.3);
}

// README, exit codes: "1 on a failure during the run (message says what and
// when)". The failing window here is t = 0.12 s; the message and cortex.log must say so
// (io/run_driver.cpp logs "run failed at t = ... s (k windows completed)").
TEST(RunFailure, MessageSaysWhen) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), divergingConfig("max_step = 1.0e7"));
  const RunResult r = runConfig(config, dir / "out", {}, dir.path());
  ASSERT_EQ(r.exit_code, 1) << describe(r);
  const std::regex when(R"(t\s*=\s*0\.12|0\.12\s*s)");
  EXPECT_TRUE(std::regex_search(r.err, when)) << "the failure message does not say when (t = 0.12 s) the run failed\n"
                                              << describe(r);
  const std::string log = readFile(dir / "out" / "cortex.log");
  EXPECT_TRUE(std::regex_search(log, when)) << "cortex.log does not record the failure\n" << log;
}

// BUG (serious: a diverged run reports success). The same runaway energy with the
// default max_step (20 nm): mech/minimizer.cpp checkBounded() only fires when a coordinate
// passes 1e9 nm or the energy falls below -1e30 pN·nm, which steps of at most 20 nm cannot
// reach within max_iterations, so every window ends "maximum iterations reached" (a
// warning), the membrane grows without bound (area ~1e14 nm^2 here, ~3e15 nm^2 after one
// window with the default max_iterations = 100000, which also takes ~5 s per window) and
// the program exits 0 with a summary of that state. max_iterations is lowered here only to
// keep the test fast; the outcome is the same with the default.
// Expected: exit 1 (a diverging energy; README exit codes, core/error.hpp).
TEST(RunFailure, UnboundedEnergyWithDefaultStepFails) {
  TempDir dir;
  std::string text = divergingConfig("max_iterations = 2000");
  text.replace(text.find("end_time = 0.3"), 14, "end_time = 0.14");
  const fs::path config = writeConfig(dir.path(), text);
  const fs::path out = dir / "out";
  const RunResult r = runConfig(config, out, {}, dir.path());
  std::string area;
  if (fs::exists(out / "summary.json"))
    area = readJson(out / "summary.json")["membranes"][0]["area"].dump();
  EXPECT_EQ(r.exit_code, 1) << "a run whose energy is unbounded below ended with exit code " << r.exit_code
                            << " (final area " << area << " nm^2, initial ~5e5 nm^2)\n"
                            << describe(r);
}

// The message of the RunError a run of `config` ends with, run in process so that a test
// can set values past the config reader's checks; empty (a failed expectation) if it
// does not fail.
std::string runErrorOf(const Config& config) {
  System system(config);
  RunObserver quiet;
  Simulation sim(system, config.simulation, config.mechanics, quiet);
  try {
    sim.run(true);
  } catch (const RunError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the run did not fail";
  return "";
}

// An energy that is not finite where the bodies start (the bundle of
// examples/bundle_protrusion.toml with an excluded-volume distance of 1e300 nm): the
// minimizer knows only the total, and the message used to end at "check parameters for
// impossible values". It names the term. The config reader refuses that distance now
// (HostileInput.StiffnessesNoRelaxationCanResolveAreRefused), so it is set past it, as
// a term that turns non-finite on the way would be.
TEST(RunFailure, ANonFiniteEnergyNamesItsTerm) {
  Config config = loadConfig(sourceDir() / "examples" / "bundle_protrusion.toml", {"simulation.end_time=0.01"});
  config.filaments->types[0].excluded_volume_distance = 1e300;
  const std::string message = runErrorOf(config);
  EXPECT_NE(message.find("the energy term \"excluded_volume\" of \"filaments\""), std::string::npos) << message;
}

// A bending modulus of 1e9 pN·nm (1.7e7 pN at 60 nm edges, past what the config reader
// accepts) converges in the shape relaxation's own coordinates and leaves ~58 pN at the
// final positions. The error said "...tolerance 0.1 pN): " and nothing after: it says why.
TEST(RunFailure, ARelaxationConvergedOnlyInItsOwnCoordinatesSaysSo) {
  Config config = parseConfig(R"([simulation]
end_time = 0.01
chemistry_window = 0.01
[[membrane]]
name = "vesicle"
shape = "sphere"
radius = 800.0
mesh_size = 60.0
)",
                              "stiff.toml", ".", {});
  config.membranes[0].mechanics.bending.modulus = Schedule(1e9);
  const std::string message = runErrorOf(config);
  EXPECT_NE(message.find("not by the forces recomputed at the final positions"), std::string::npos) << message;
}

// Membranes do not push on each other: two that come to pass through each other during a
// run stop it (exit 1) instead of going on with their insides overlapping. Here the
// second vesicle is moved 150 nm into the first after the start's check, as a swelling or
// drifting one would come; the first relaxation's check finds them.
TEST(RunFailure, MembranesThatComeToPassThroughEachOtherStopTheRun) {
  const Config config = parseConfig(R"([simulation]
end_time = 0.01
chemistry_window = 0.01
[[membrane]]
name = "left"
shape = "sphere"
center = [0.0, 0.0, 0.0]
radius = 300.0
mesh_size = 60.0
[[membrane]]
name = "right"
shape = "sphere"
center = [620.0, 0.0, 0.0]
radius = 300.0
mesh_size = 60.0
)",
                                    "apart.toml", ".", {});
  System system(config);
  for (Vec3& x : system.membranes()[1]->mesh().positions()) x.x() -= 150.0;
  RunObserver quiet;
  Simulation sim(system, config.simulation, config.mechanics, quiet);
  try {
    sim.run(true);
    ADD_FAILURE() << "the run did not fail";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("membranes \"left\" and \"right\" pass through each other"),
              std::string::npos)
        << e.what();
  }
}

// A stop request is polled within windows too (OutputObserver::duringWindow abandons a
// window that outlasts its grace): during the relaxations of membranes and filaments as
// during chemistry (Faults.SigtermAbandonsAWindowThatRunsOnTooLong), and what it throws
// ends the run at once, from either relaxation.
TEST(RunFailure, AStopWithinAWindowIsPolledDuringRelaxations) {
  struct StopAt final : RunObserver {
    int calls = 0, stop_at;
    explicit StopAt(int n) : stop_at(n) {}
    void duringWindow() override {
      if (++calls == stop_at) throw RunStopped("stop");
    }
  };
  for (const char* example : {"vesicle_relax.toml", "bundle_protrusion.toml"}) {
    Config config = loadConfig(sourceDir() / "examples" / example, {"simulation.end_time=0.01"});
    System system(config);
    StopAt counting(-1);
    Simulation(system, config.simulation, config.mechanics, counting).run(true);
    EXPECT_GT(counting.calls, 0) << example;
    System again(config);
    StopAt stopping(1);
    EXPECT_THROW(Simulation(again, config.simulation, config.mechanics, stopping).run(true), RunStopped) << example;
    EXPECT_EQ(stopping.calls, 1) << example;
  }
}

// A reduced volume of 0.999 is more than a 368-vertex sphere encloses at its area (0.9972):
// every relaxation failed its constraints and the run went on to exit 0 with warnings.
TEST(RunFailure, AReducedVolumeTheMeshCannotReachStopsTheRun) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), R"([simulation]
end_time = 0.02
chemistry_window = 0.005
[[membrane]]
name = "vesicle"
shape = "sphere"
radius = 300.0
mesh_size = 60.0
reduced_volume = 0.999
)");
  const RunResult r = runConfig(config, dir / "out", {}, dir.path());
  EXPECT_EQ(r.exit_code, 1) << describe(r);
  EXPECT_NE(r.err.find("area and volume targets cannot be held together"), std::string::npos) << describe(r);
}

// A filament growing out of the compartment grid (no [boundary] holds it): its plus end
// reacted with the edge compartment wherever it was, and one filament grew 3 µm out of a
// one-compartment grid on that compartment's monomers, exit 0. Now the run stops once a
// bead is more than a tenth of a compartment (50 nm) outside; with a [boundary] (walls at
// the grid's faces) the same filament stalls at the wall and the run finishes.
TEST(RunFailure, AFilamentGrowingOutOfTheGridStopsTheRun) {
  TempDir dir;
  const std::string text = R"([simulation]
seed = 1
end_time = 1.0
chemistry_window = 0.05
snapshot_interval = 0.5
[compartments]
size = 500.0
shape = [1, 1, 1]
[[species]]
name = "G"
diffusion = 2.0e7
concentration = 20.0
[[filament_type]]
name = "actin"
monomer_species = "G"
[[filaments]]
count = 1
length = 108.0
placement = "bundle"
center = [400.0, 250.0, 250.0]
direction = [1.0, 0.0, 0.0]
)";
  const RunResult out = runConfig(writeConfig(dir.path(), text, "out.toml"), dir / "out", {}, dir.path());
  EXPECT_EQ(out.exit_code, 1) << describe(out);
  EXPECT_NE(out.err.find("filament 0 reached ["), std::string::npos) << describe(out);
  EXPECT_NE(out.err.find("nm outside the compartment grid (the box from [0, 0, 0] to [500, 500, 500] nm; 0.1 of a "
                         "compartment, 50 nm, is tolerated)"),
            std::string::npos)
      << describe(out);
  EXPECT_TRUE(fs::exists(dir / "out" / "snapshots" / "000000.h5")) << describe(out);
  const RunResult walled =
      runConfig(writeConfig(dir.path(), text + "[boundary]\n", "walled.toml"), dir / "walled", {}, dir.path());
  EXPECT_EQ(walled.exit_code, 0) << describe(walled);
}

}  // namespace
}  // namespace cortex::cli_test
