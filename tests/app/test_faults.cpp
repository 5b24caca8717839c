// Issue 11: runs that survive faults. SIGKILL at random moments, SIGTERM, a second
// signal, a full disk, damaged and foreign checkpoints: the outputs stay whole, resume
// gives the uninterrupted result, and failures are errors naming the file.
#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <random>
#include <thread>

#include "app/cli_helpers.hpp"
#include "app/snapshots.hpp"
#include "io/checkpoint.hpp"

namespace cortex::cli_test {
namespace {

// A vesicle shrinking in a compartment grid with confined species: membrane, chemistry
// and remeshing state, a snapshot and a checkpoint at every one of 20 windows (~0.7 s).
std::string snapshotHeavyConfig() {
  return R"([simulation]
seed = 5
end_time = 0.2
chemistry_window = 0.01
snapshot_interval = 0.01

[[membrane]]
name = "vesicle"
shape = "sphere"
center = [400.0, 400.0, 400.0]
radius = 200.0
mesh_size = 50.0
remesh = true
reduced_volume = [[0.0, 1.0], [0.2, 0.85]]

[compartments]
size = 100.0
shape = [8, 8, 8]

[[species]]
name = "A"
diffusion = 1.0e6
copies = 3000
inside = "vesicle"

[[species]]
name = "B"
diffusion = 1.0e6
copies = 3000
outside = "vesicle"

[[reaction]]
equation = "2 A -> A"
rate = 0.01
)";
}

bool waitForFile(const fs::path& file, double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!fs::exists(file)) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

// Every snapshot the index lists is readable, with a mesh and the compartment copies.
void expectListedSnapshotsReadable(const fs::path& outdir, const std::string& when) {
  if (!fs::exists(outdir / "trajectory.h5")) return;
  std::vector<Snapshot> snaps;
  try {
    snaps = readSnapshots(outdir / "trajectory.h5");
  } catch (const std::exception& e) {
    ADD_FAILURE() << when << ": a listed snapshot is unreadable: " << e.what();
    return;
  }
  for (const Snapshot& s : snaps) {
    EXPECT_FALSE(s.vertices.empty()) << when << ", " << s.group;
    EXPECT_FALSE(s.triangles.empty()) << when << ", " << s.group;
  }
}

struct Reference {
  nlohmann::json summary;
  double seconds = 0.0;
};

Reference uninterrupted(const TempDir& dir, const fs::path& config) {
  const auto start = std::chrono::steady_clock::now();
  const RunResult r = runConfig(config, dir / "reference", {"--threads", "1"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  return {comparableSummary(dir / "reference"),
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

// SIGKILL at 50 random moments of a run (seeded: the same moments every time, spread
// over the whole run including its start-up and its last writes). After each kill every
// snapshot the index lists is readable, and the run resumed from whatever checkpoint
// survived (or started again when it died before the first) ends with the uninterrupted
// run's summary.
TEST(Faults, SigkillAtFiftyRandomMomentsThenResumeGivesTheUninterruptedResult) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), snapshotHeavyConfig());
  const Reference ref = uninterrupted(dir, config);
  ASSERT_FALSE(::testing::Test::HasFailure());
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> moment(0.0, 1.1 * ref.seconds);
  int killed_before_checkpoint = 0, killed_mid_run = 0, finished_first = 0;
  for (int k = 0; k < 50; ++k) {
    const fs::path out = dir / ("kill" + std::to_string(k));
    const double delay = moment(rng);
    const std::string when = "kill " + std::to_string(k) + " after " + std::to_string(delay) + " s";
    const pid_t pid = spawnCortex({"run", config.string(), "-o", out.string(), "-q", "--threads", "1"});
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    kill(pid, SIGKILL);
    const int code = waitFor(pid);
    if (code == 0) {
      ++finished_first;
    } else {
      ASSERT_EQ(code, 128 + SIGKILL) << when;
    }
    expectListedSnapshotsReadable(out, when);
    EXPECT_FALSE(fs::exists(out / "summary.json.tmp")) << when;
    RunResult r;
    if (fs::exists(out / "checkpoint.h5")) {
      ++killed_mid_run;
      r = runCortex({"run", "--resume", out.string(), "-q", "--threads", "1"}, dir.path());
    } else {
      ++killed_before_checkpoint;
      r = runConfig(config, out, {"--threads", "1", "--overwrite"}, dir.path());
    }
    ASSERT_EQ(r.exit_code, 0) << when << "\n" << describe(r);
    EXPECT_EQ(comparableSummary(out), ref.summary) << when;
    expectListedSnapshotsReadable(out, when + ", resumed");
    EXPECT_EQ(readSnapshots(out / "trajectory.h5").size(), 21u) << when;
    fs::remove_all(out);
  }
  // The moments must have hit the run in its different phases.
  EXPECT_GT(killed_mid_run, 20);
  RecordProperty("killed_before_first_checkpoint", killed_before_checkpoint);
  RecordProperty("finished_before_the_kill", finished_first);
}

// SIGTERM mid-run: the window in progress finishes, a checkpoint and a log line are
// written, the exit code is 3; resuming gives the uninterrupted run's summary and
// snapshots, bit for bit.
TEST(Faults, SigtermStopsAfterACheckpointAndResumesBitIdentically) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), snapshotHeavyConfig());
  const Reference ref = uninterrupted(dir, config);
  const fs::path out = dir / "stopped";
  const pid_t pid = spawnCortex({"run", config.string(), "-o", out.string(), "-q", "--threads", "1"});
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForFile(out / "snapshots" / "000005.h5", 30.0));
  kill(pid, SIGTERM);
  ASSERT_EQ(waitFor(pid), 3);
  const std::string log = readFile(out / "cortex.log");
  EXPECT_NE(log.find("stopped by signal 15"), std::string::npos) << log;
  EXPECT_TRUE(fs::exists(out / "checkpoint.h5"));
  EXPECT_FALSE(fs::exists(out / "summary.json")) << "a stopped run has no final summary";
  const RunResult r = runCortex({"run", "--resume", out.string(), "-q", "--threads", "1"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(comparableSummary(out), ref.summary);
  const auto a = readSnapshots(dir / "reference" / "trajectory.h5"), b = readSnapshots(out / "trajectory.h5");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].vertices, b[i].vertices) << "snapshot " << i;
    EXPECT_EQ(a[i].triangles, b[i].triangles) << "snapshot " << i;
  }
}

// SIGTERM during the set-up (here meshing a 1 µm vesicle at 16 nm, which takes longer
// than the 0.15 s before the signal): the handler is installed before anything else, so
// the run still stops after its first relaxation and checkpoint with exit 3. (It was
// installed after the set-up, and such a signal killed the run: exit 143, no output.)
TEST(Faults, SigtermDuringTheSetUpStopsAfterTheFirstCheckpoint) {
  TempDir dir;
  const fs::path out = dir / "stopped";
  const pid_t pid = spawnCortex({"run", CORTEX_SOURCE_DIR "/examples/vesicle_osmotic_shrink.toml", "-o", out.string(),
                                 "-q", "--threads", "1", "--set", "membrane.0.mesh_size=16"});
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(150));
  kill(pid, SIGTERM);
  ASSERT_EQ(waitFor(pid), 3);
  EXPECT_TRUE(fs::exists(out / "checkpoint.h5"));
  EXPECT_NE(readFile(out / "cortex.log").find("stopped by signal 15"), std::string::npos);
}

// Starts a run into dir/out of one window of pure chemistry, `seconds` long in simulated
// time (about half that in wall time here), and returns 300 ms into that window, after
// its first snapshot; its pid, or -1 (a failed expectation) if it did not get there.
pid_t startIntoOneChemistryWindow(const TempDir& dir, double seconds) {
  const fs::path config = writeConfig(dir.path(), fmt::format(R"([simulation]
end_time = {0:.1f}
chemistry_window = {0:.1f}
snapshot_interval = {0:.1f}
[compartments]
size = 100.0
shape = [20, 20, 20]
[[species]]
name = "A"
diffusion = 1.0e6
copies = 4000
)",
                                                              seconds));
  const fs::path out = dir / "out";
  const pid_t pid = spawnCortex({"run", config.string(), "-o", out.string(), "-q", "--threads", "1"});
  if (pid <= 0 || !waitForFile(out / "snapshots" / "000000.h5", 30.0)) {
    ADD_FAILURE() << "the run did not reach its first window";
    return -1;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // into the window
  return pid;
}

// A stop waits for the window in progress only so long (10 s, kStopGraceSeconds): here one
// window of chemistry takes about half a minute, and the run ends about 10 s after SIGTERM
// with exit 3, the window abandoned, the checkpoint of t = 0 kept and the log saying so.
// (It waited for the window's end; a relaxation of 15 minutes ignored SIGTERM.)
TEST(Faults, SigtermAbandonsAWindowThatRunsOnTooLong) {
  TempDir dir;
  const fs::path out = dir / "out";
  const pid_t pid = startIntoOneChemistryWindow(dir, 60.0);
  ASSERT_GT(pid, 0);
  const auto signalled = std::chrono::steady_clock::now();
  kill(pid, SIGTERM);
  ASSERT_EQ(waitFor(pid), 3);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
  EXPECT_GT(seconds, 9.0);   // the grace of 10 s, less the poll interval
  EXPECT_LT(seconds, 20.0);  // not the ~30 s the window takes
  const std::string log = readFile(out / "cortex.log");
  EXPECT_NE(log.find("stopped by signal 15 during window 1 (0 completed)"), std::string::npos) << log;
  EXPECT_NE(log.find("checkpoint of t = 0 s is kept"), std::string::npos) << log;
  EXPECT_TRUE(fs::exists(out / "checkpoint.h5"));
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

// A second signal stops at once (the default action), without waiting for the window.
TEST(Faults, SecondSignalStopsAtOnce) {
  TempDir dir;
  // One window of a few seconds: the first signal waits for its end.
  const pid_t pid = startIntoOneChemistryWindow(dir, 10.0);
  ASSERT_GT(pid, 0);
  kill(pid, SIGINT);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  kill(pid, SIGINT);
  EXPECT_EQ(waitFor(pid), 128 + SIGINT);
}

// Writes that fail with "no space left on device" once a byte budget is spent (an
// LD_PRELOAD shim around write(2), tests/shims/enospc_write.cpp), at budgets that cut the
// run at different files: every run exits 1 naming the file it could not write, none
// crashes, summary.json is whole or absent, no temporary file is left, and whatever
// snapshots it kept are readable.
TEST(Faults, FullDiskExitsOneNamingTheFileAndLeavesNoBrokenFile) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), snapshotHeavyConfig());
  for (long budget : {0L, 50'000L, 200'000L, 600'000L, 1'500'000L, 2'800'000L}) {
    const std::string when = "write budget " + std::to_string(budget) + " bytes";
    const fs::path out = dir / ("full" + std::to_string(budget));
    const RunResult r = runConfig(config, out, {"--threads", "1"}, dir.path(),
                                  {"LD_PRELOAD=" + std::string(CORTEX_ENOSPC_SHIM),
                                   "CORTEX_TEST_WRITE_BUDGET=" + std::to_string(budget)});
    ASSERT_EQ(r.exit_code, 1) << when << "\n" << describe(r);
    EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << when << "\n" << describe(r);
    EXPECT_NE(r.err.find(out.string()), std::string::npos) << "the message names the file\n" << describe(r);
    if (fs::exists(out / "summary.json")) {
      EXPECT_NO_THROW(readJson(out / "summary.json")) << when;
    }
    for (const auto& entry : fs::recursive_directory_iterator(out))
      EXPECT_NE(entry.path().extension(), ".tmp") << when << ": " << entry.path();
    expectListedSnapshotsReadable(out, when);
  }
}

// The same with a real full file system where one can be mounted (a 400 KB tmpfs in a
// user namespace); skipped where the sandbox forbids it.
TEST(Faults, FullTmpfsExitsOneNamingTheFile) {
  if (std::system("unshare -rm true >/dev/null 2>&1") != 0) GTEST_SKIP() << "no user namespaces here";
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), snapshotHeavyConfig());
  const fs::path mount = dir / "mnt";
  fs::create_directories(mount);
  const std::string script = "mount -t tmpfs -o size=400k none " + shellQuote(mount.string()) + " && " +
                             shellQuote(cortexBinary().string()) + " run " + shellQuote(config.string()) + " -o " +
                             shellQuote((mount / "out").string()) + " -q --threads 1";
  const int status = std::system(("unshare -rm sh -c " + shellQuote(script) + " >" +
                                  shellQuote((dir / "tmpfs_out.txt").string()) + " 2>&1")
                                     .c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1) << readFile(dir / "tmpfs_out.txt");
  EXPECT_NE(readFile(dir / "tmpfs_out.txt").find("No space left on device"), std::string::npos)
      << readFile(dir / "tmpfs_out.txt");
}

// Single bytes flipped at 25 places of a checkpoint: a resume either refuses it (exit 2,
// naming the checkpoint) or, where the byte carries nothing (the header's padding), gives
// the uninterrupted result. A checkpoint copied from another run is refused.
TEST(Faults, DamagedOrForeignCheckpointsAreRefused) {
  TempDir dir;
  const auto config_text = [](double end) {
    std::string text = snapshotHeavyConfig();
    text.replace(text.find("end_time = 0.2"), 14, "end_time = " + std::to_string(end));
    return text;
  };
  const fs::path full = writeConfig(dir.path(), config_text(0.2), "full.toml");
  const fs::path half = writeConfig(dir.path(), config_text(0.1), "half.toml");
  const Reference ref = uninterrupted(dir, full);
  ASSERT_EQ(runConfig(half, dir / "half", {"--threads", "1"}, dir.path()).exit_code, 0);
  const std::string original = readFile(dir / "half" / "checkpoint.h5");
  std::mt19937 rng(11);
  std::uniform_int_distribution<std::size_t> where(0, original.size() - 1);
  int refused = 0;
  for (int k = 0; k < 25; ++k) {
    const fs::path out = dir / ("flip" + std::to_string(k));
    fs::copy(dir / "half", out, fs::copy_options::recursive);
    std::string bytes = original;
    const std::size_t at = k < 3 ? static_cast<std::size_t>(k) * 20 : where(rng);  // the header too
    bytes[at] = static_cast<char>(bytes[at] ^ 0x5a);
    writeFile(out / "checkpoint.h5", bytes);
    const RunResult r = runCortex({"run", "--resume", out.string(), "--set", "simulation.end_time=0.2", "-q"},
                                  dir.path());
    const std::string when = "byte " + std::to_string(at) + " of " + std::to_string(bytes.size());
    if (r.exit_code == 2) {
      ++refused;
      EXPECT_NE(r.err.find("checkpoint.h5"), std::string::npos) << when << "\n" << describe(r);
    } else {
      ASSERT_EQ(r.exit_code, 0) << when << "\n" << describe(r);
      EXPECT_EQ(comparableSummary(out), ref.summary) << when << ": resumed from a damaged checkpoint to another result";
    }
  }
  EXPECT_GE(refused, 20);

  // Another run's checkpoint (another seed) in this run's folder.
  const fs::path other = dir / "other";
  ASSERT_EQ(runConfig(half, other, {"--threads", "1", "--seed", "6"}, dir.path()).exit_code, 0);
  const fs::path mixed = dir / "mixed";
  fs::copy(dir / "half", mixed, fs::copy_options::recursive);
  fs::copy_file(other / "checkpoint.h5", mixed / "checkpoint.h5", fs::copy_options::overwrite_existing);
  const RunResult r = runCortex({"run", "--resume", mixed.string(), "-q"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("another run"), std::string::npos) << describe(r);
  // Its trajectory index copied in too: the snapshots before the checkpoint are still this
  // run's (that resumed to exit 0, the two runs' snapshots one after the other).
  fs::copy_file(other / "trajectory.h5", mixed / "trajectory.h5", fs::copy_options::overwrite_existing);
  const RunResult both = runCortex({"run", "--resume", mixed.string(), "--set", "simulation.end_time=0.2", "-q"},
                                   dir.path());
  EXPECT_EQ(both.exit_code, 2) << describe(both);
  EXPECT_NE(both.err.find("belongs to another run"), std::string::npos) << describe(both);
}

// A checkpoint edited and stamped again passes its checksum; what it says must still
// agree with itself. An edited window count ran a half-done run to its end with exit 0,
// a snapshot count of 0 deleted the snapshots, one edited down deleted the later ones and
// renumbered the rest (exit 0), one of -5 crashed the resume, one of 2^40 ran out of
// memory, a missing dataset was an internal error (exit 1).
TEST(Faults, EditedCheckpointsThatPassTheirChecksumAreRefused) {
  TempDir dir;
  std::string text = snapshotHeavyConfig();
  text.replace(text.find("end_time = 0.2"), 14, "end_time = 0.1");
  const fs::path half = writeConfig(dir.path(), text, "half.toml");
  ASSERT_EQ(runConfig(half, dir / "half", {"--threads", "1"}, dir.path()).exit_code, 0);
  const auto snapshots = [](const fs::path& out) {
    return std::distance(fs::directory_iterator(out / "snapshots"), fs::directory_iterator{});
  };
  const auto written = snapshots(dir / "half");
  const std::vector<std::pair<std::string, std::function<void(Checkpoint&)>>> edits = {
      {"no snapshots", [](Checkpoint& c) { c.header.next_snapshot = 0; }},
      {"negative snapshots", [](Checkpoint& c) { c.header.next_snapshot = -5; }},
      {"2^40 snapshots", [](Checkpoint& c) { c.header.next_snapshot = std::int64_t{1} << 40; }},
      {"fewer snapshots", [](Checkpoint& c) { c.header.next_snapshot = 3; }},
      {"windows past the end", [](Checkpoint& c) { c.state.step = 100; }},
      {"too few windows", [](Checkpoint& c) { c.state.step = 3; }},
      {"negative windows", [](Checkpoint& c) { c.state.step = -1; }},
      {"time NaN", [](Checkpoint& c) { c.state.time = std::nan(""); }},
  };
  for (const auto& [what, edit] : edits) {
    const fs::path out = dir / "edited";
    fs::remove_all(out);
    fs::copy(dir / "half", out, fs::copy_options::recursive);
    Checkpoint cp = readCheckpoint(out / "checkpoint.h5");
    edit(cp);
    writeCheckpoint(out / "checkpoint.h5", cp.header, cp.state);
    const RunResult r = runCortex({"run", "--resume", out.string(), "--set", "simulation.end_time=0.2", "-q"},
                                  dir.path());
    EXPECT_EQ(r.exit_code, 2) << what << "\n" << describe(r);
    EXPECT_NE(r.err.find(what == "2^40 snapshots" ? "snapshot files" : "checkpoint.h5"), std::string::npos)
        << what << "\n" << describe(r);
    EXPECT_EQ(snapshots(out), written) << what << ": the snapshots written before the checkpoint are kept";
  }
  // The same round trip without an edit resumes.
  const fs::path plain = dir / "plain";
  fs::copy(dir / "half", plain, fs::copy_options::recursive);
  const Checkpoint cp = readCheckpoint(plain / "checkpoint.h5");
  writeCheckpoint(plain / "checkpoint.h5", cp.header, cp.state);
  const RunResult r = runCortex({"run", "--resume", plain.string(), "--set", "simulation.end_time=0.2", "-q"},
                                dir.path());
  EXPECT_EQ(r.exit_code, 0) << describe(r);
}

}  // namespace
}  // namespace cortex::cli_test
