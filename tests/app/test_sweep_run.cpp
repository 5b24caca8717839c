// `cortex sweep` end to end (issue 12, item 4): a 3 x 2 grid with 2 seeds (12 members)
// as plain processes and under `mpirun -n 4` gives the same table; an interrupted sweep
// (SIGKILL or SIGTERM) completes on rerun without redoing finished members; a member
// that fails is recorded with its message while the others finish; bad input is refused
// before anything runs.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <map>
#include <thread>

#include "app/cli_helpers.hpp"
#include "io/hdf5_file.hpp"
#include "io/observables.hpp"

namespace cortex::cli_test {
namespace {

// Chemistry only (seeds matter, no relaxation): a dimerization in a 3^3 grid, about
// 0.1-0.2 s per member, a checkpoint every 0.05 s so an interrupted member resumes.
const char* const kBase = R"([simulation]
end_time = 0.2
chemistry_window = 0.01
snapshot_interval = 0.05

[compartments]
size = 500.0
shape = [3, 3, 3]

[[species]]
name = "A"
diffusion = 2.0e7
copies = 20000

[[species]]
name = "B"
diffusion = 2.0e6
copies = 0

[[reaction]]
equation = "2 A -> B"
rate = 0.01

[[reaction]]
equation = "B -> 2 A"
rate = 1.0
)";

const char* const kSweep = R"(base = "base.toml"
seeds = 2
[grid]
"reaction.0.rate" = [0.005, 0.01, 0.02]
"simulation.end_time" = [0.1, 0.2]
)";

struct Sweep {
  TempDir dir;
  fs::path file = writeConfig(dir.path(), kSweep, "sweep.toml");
  Sweep() { writeConfig(dir.path(), kBase, "base.toml"); }
  std::vector<std::string> args(const fs::path& out) const {
    return {"sweep", file.string(), "-o", out.string(), "--parallel", "2", "-q"};
  }
  RunResult run(const fs::path& out) const { return runCortex(args(out), dir.path()); }
};

// summary.json modification times of the members that have one.
std::map<std::string, fs::file_time_type> finishedMembers(const fs::path& out) {
  std::map<std::string, fs::file_time_type> finished;
  for (const auto& entry : fs::directory_iterator(out / "members"))
    if (fs::exists(entry.path() / "summary.json"))
      finished[entry.path().filename().string()] = fs::last_write_time(entry.path() / "summary.json");
  return finished;
}

// Starts the sweep, waits until `done` members have finished, calls `meanwhile`, then
// sends `signal`; returns the sweep's exit code and which members had finished.
std::pair<int, std::map<std::string, fs::file_time_type>> interrupt(const Sweep& s, const fs::path& out,
                                                                    std::size_t done, int signal,
                                                                    const std::function<void()>& meanwhile = [] {}) {
  const pid_t pid = spawnCortex(s.args(out));
  EXPECT_GT(pid, 0);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while ((!fs::exists(out / "members") || finishedMembers(out).size() < done) &&
         std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  meanwhile();
  kill(pid, signal);
  const int code = waitFor(pid);
  return {code, finishedMembers(out)};
}

std::size_t countLines(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) ++n;
  return n;
}

TEST(SweepRun, TwelveMembersAsPlainProcessesGiveOneTableWithSweptColumns) {
  const Sweep s;
  const RunResult r = s.run(s.dir / "out");
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const std::string csv = readFile(s.dir / "out" / "sweep.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')).rfind("member,status,seed,reaction.0.rate,simulation.end_time,outdir,message,time,",
                                                0),
            0u)
      << csv;
  EXPECT_EQ(csv.find("wall_seconds"), std::string::npos) << "wall-clock time would make equal sweeps differ";
  EXPECT_EQ(countLines(csv, "\n"), 13u);
  EXPECT_NE(csv.find("\n0,ok,1,0.0050000000000000001,0.10000000000000001,members/0000,,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n11,ok,2,0.02,0.20000000000000001,members/0011,,"), std::string::npos) << csv;
  // Each member is an ordinary run whose summary the table repeats.
  const nlohmann::json summary = readJson(s.dir / "out" / "members" / "0011" / "summary.json");
  EXPECT_EQ(summary["seed"], 2);
  EXPECT_DOUBLE_EQ(summary["time"].get<double>(), 0.2);

  const h5::File h5 = h5::File::openReadOnly(s.dir / "out" / "sweep.h5");
  h5::Shape shape;
  const std::vector<double> table = h5.readDoubles("/table", &shape);
  ASSERT_EQ(shape.size(), 2u);
  EXPECT_EQ(shape[0], 12u);
  const std::vector<std::string> columns = splitColumns(h5.attributeString("/table", "columns"));
  ASSERT_EQ(columns.size(), shape[1]);
  const auto b = std::find(columns.begin(), columns.end(), "chemistry.species.B") - columns.begin();
  ASSERT_LT(static_cast<std::size_t>(b), columns.size());
  EXPECT_EQ(table[11 * shape[1] + b], summary["chemistry"]["species"]["B"].get<double>());
  EXPECT_EQ(h5.readStrings("/strings/status"), std::vector<std::string>(12, "ok"));

  // A second run finds every member finished: nothing reruns, the table is the same.
  const auto before = finishedMembers(s.dir / "out");
  const RunResult again = s.run(s.dir / "out");
  ASSERT_EQ(again.exit_code, 0) << describe(again);
  EXPECT_EQ(finishedMembers(s.dir / "out"), before);
  EXPECT_EQ(readFile(s.dir / "out" / "sweep.csv"), csv);
}

TEST(SweepRun, UnderMpirunWithFourRanksGivesTheSameTable) {
#ifndef CORTEX_MPIEXEC
  GTEST_SKIP() << "cortex was built without MPI";
#else
  const fs::path mpiexec = CORTEX_MPIEXEC;
  if (!fs::exists(mpiexec)) GTEST_SKIP() << mpiexec << " not found";
  const Sweep s;
  const RunResult plain = s.run(s.dir / "plain");
  ASSERT_EQ(plain.exit_code, 0) << describe(plain);
  std::vector<std::string> args{"-n", "4", cortexBinary().string()};
  const std::vector<std::string> sweep = s.args(s.dir / "mpi");
  args.insert(args.end(), sweep.begin(), sweep.end());
  // CI runs as root in a container on 2 cores: Open MPI refuses root and more ranks than
  // cores unless told, and its single-copy shared memory needs ptrace rights containers
  // lack. Environment settings, so that other launchers ignore them.
  const RunResult mpi = runProgram(mpiexec, args, s.dir.path(),
                                   {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1",
                                    "OMPI_MCA_rmaps_base_oversubscribe=1",
                                    "OMPI_MCA_btl_vader_single_copy_mechanism=none"});
  ASSERT_EQ(mpi.exit_code, 0) << describe(mpi);
  EXPECT_EQ(readFile(s.dir / "mpi" / "sweep.csv"), readFile(s.dir / "plain" / "sweep.csv"));
  EXPECT_EQ(countLines(readFile(s.dir / "mpi" / "sweep.log"), " ok after "), 12u);
#endif
}

TEST(SweepRun, KilledSweepCompletesOnRerunWithoutRedoingFinishedMembers) {
  const Sweep s;
  const RunResult whole = s.run(s.dir / "whole");
  ASSERT_EQ(whole.exit_code, 0) << describe(whole);
  const fs::path out = s.dir / "killed";
  const auto [code, finished] = interrupt(s, out, 3, SIGKILL);
  EXPECT_EQ(code, 128 + SIGKILL);
  ASSERT_GE(finished.size(), 3u);
  ASSERT_LT(finished.size(), 12u) << "the sweep ended before it could be killed";
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));

  const RunResult rerun = s.run(out);
  ASSERT_EQ(rerun.exit_code, 0) << describe(rerun);
  const auto after = finishedMembers(out);
  for (const auto& [member, time] : finished) EXPECT_EQ(after.at(member), time) << member << " ran again";
  EXPECT_EQ(countLines(readFile(out / "sweep.log"), "finished before: skipped"), finished.size());
  EXPECT_EQ(readFile(out / "sweep.csv"), readFile(s.dir / "whole" / "sweep.csv"));
}

TEST(SweepRun, TerminatedSweepStopsItsMembersWritesWhatIsDoneAndContinuesAndHoldsItsFolder) {
  const Sweep s;
  const RunResult whole = s.run(s.dir / "whole");
  ASSERT_EQ(whole.exit_code, 0) << describe(whole);
  const fs::path out = s.dir / "stopped";
  RunResult second;  // a second sweep into the folder while the first runs
  const auto [code, finished] = interrupt(s, out, 2, SIGTERM, [&] { second = s.run(out); });
  EXPECT_EQ(second.exit_code, 2) << describe(second);
  EXPECT_NE(second.err.find("another cortex sweep is running"), std::string::npos) << describe(second);
  ASSERT_LT(finished.size(), 12u) << "the sweep ended before it could be stopped";
  EXPECT_EQ(code, 3);
  const std::string partial = readFile(out / "sweep.csv");
  EXPECT_EQ(countLines(partial, ",ok,"), finished.size()) << partial;
  EXPECT_GT(countLines(partial, ",pending,") + countLines(partial, ",stopped,"), 0u) << partial;

  const RunResult rerun = s.run(out);
  ASSERT_EQ(rerun.exit_code, 0) << describe(rerun);
  const auto after = finishedMembers(out);
  for (const auto& [member, time] : finished) EXPECT_EQ(after.at(member), time) << member << " ran again";
  EXPECT_EQ(readFile(out / "sweep.csv"), readFile(s.dir / "whole" / "sweep.csv"));
}

TEST(SweepRun, AFailingMemberIsRecordedWithItsMessageAndTheOthersFinish) {
  TempDir dir;
  // The base shrinks a vesicle; 3 iterations per relaxation end far from equilibrium at
  // the first window (exit code 1 from that member's run), which no check can foresee.
  writeConfig(dir.path(), R"([simulation]
end_time = 0.04
chemistry_window = 0.02
snapshot_interval = 0.02
[mechanics]
force_tolerance = 0.001
[[membrane]]
name = "shrinking"
shape = "sphere"
radius = 300.0
mesh_size = 60.0
reduced_volume = [[0.0, 1.0], [0.04, 0.9]]
)",
              "base.toml");
  const fs::path file = writeConfig(dir.path(), R"(base = "base.toml"
[[members]]
"mechanics.max_iterations" = 100000
[[members]]
"mechanics.max_iterations" = 3
[[members]]
"membrane.0.bending_modulus" = 50.0
)",
                                    "sweep.toml");
  const RunResult r = runCortex({"sweep", file.string(), "-o", (dir / "out").string(), "--parallel", "2", "-q"},
                                dir.path());
  EXPECT_EQ(r.exit_code, 1) << describe(r);
  const h5::File h5 = h5::File::openReadOnly(dir / "out" / "sweep.h5");
  EXPECT_EQ(h5.readStrings("/strings/status"), (std::vector<std::string>{"ok", "failed", "ok"}));
  const std::string message = h5.readStrings("/strings/message")[1];
  EXPECT_NE(message.find("exit code 1: run failed:"), std::string::npos) << message;
  EXPECT_NE(message.find("far from equilibrium"), std::string::npos) << message;
  const std::string csv = readFile(dir / "out" / "sweep.csv");
  EXPECT_NE(csv.find("\n1,failed,1,3,nan,members/0001,\"exit code 1: run failed:"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n2,ok,1,nan,50,members/0002,,"), std::string::npos) << csv;
}

TEST(SweepRun, BadInputIsRefusedBeforeAnyMemberRuns) {
  const Sweep s;
  // A key the base config does not have: caught when member 0 is checked.
  const fs::path bad = writeConfig(s.dir.path(), "base = \"base.toml\"\n[grid]\n\"reaction.0.rat\" = [1.0, 2.0]\n",
                                   "bad.toml");
  RunResult r = runCortex({"sweep", bad.string(), "-o", (s.dir / "out").string()}, s.dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find(bad.string()), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find("member 0 (reaction.0.rat=1.0)"), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find("reaction.0.rat"), std::string::npos) << describe(r);
  EXPECT_FALSE(fs::exists(s.dir / "out")) << "nothing is written before every member is checked";

  // A value only one grid point gets wrong: refused as well, naming that member.
  const fs::path negative = writeConfig(
      s.dir.path(), "base = \"base.toml\"\n[grid]\n\"simulation.end_time\" = [0.1, -1.0]\n", "negative.toml");
  r = runCortex({"sweep", negative.string(), "-o", (s.dir / "out").string()}, s.dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("member 1 (simulation.end_time=-1.0)"), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find("end_time"), std::string::npos) << describe(r);

  r = runCortex({"check", negative.string()}, s.dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  r = runCortex({"check", s.file.string()}, s.dir.path());
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_NE(r.out.find("ok (12 members"), std::string::npos) << describe(r);

  r = runCortex({"sweep", s.file.string(), "--dry-run"}, s.dir.path());
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(countLines(r.out, "\n"), 12u) << describe(r);
  EXPECT_NE(r.out.find("members/0011  seed 2  reaction.0.rate=0.02 simulation.end_time=0.2 simulation.seed=2"),
            std::string::npos)
      << describe(r);

  // A sweep file changed after its members ran: their folders are another config's runs.
  ASSERT_EQ(s.run(s.dir / "out").exit_code, 0);
  writeConfig(s.dir.path(), std::string(kSweep).replace(std::string(kSweep).find("0.005"), 5, "0.004"), "sweep.toml");
  r = s.run(s.dir / "out");
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("another config"), std::string::npos) << describe(r);
}

}  // namespace
}  // namespace cortex::cli_test
