// Issue 11: output folders and resumes a careless user gives: folders that cannot hold a
// run or hold another run's results, --overwrite beside files of one's own, and resume
// options, overrides or folders it cannot honour. Each is an error (exit 2) naming the
// option, key or path, and nothing of the user's is lost.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <string>
#include <vector>

#include "app/cli_helpers.hpp"
#include "app/hostile_configs.hpp"

namespace cortex::cli_test {
namespace {

TEST(HostileInput, OutputFoldersThatCannotHoldARunAreRefused) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), kVesicle);
  writeFile(dir / "a_file", "x");
  RunResult r = runConfig(config, dir / "a_file", {}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("a_file"), std::string::npos) << describe(r);
  if (geteuid() != 0) {  // root writes anywhere
    fs::create_directories(dir / "read_only");
    fs::permissions(dir / "read_only", fs::perms::owner_read | fs::perms::owner_exec);
    r = runConfig(config, dir / "read_only", {}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << describe(r);
    EXPECT_NE(r.err.find("read_only"), std::string::npos) << describe(r);
    fs::permissions(dir / "read_only", fs::perms::owner_all);
  }
}

// One run per folder: a second run into a folder with results is refused (it used to mix
// the new trajectory with the old summary and checkpoint, and a resume then continued the
// old run); --overwrite replaces them.
TEST(HostileInput, OutputFolderWithAnotherRunsResultsNeedsOverwrite) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), kVesicle);
  const fs::path out = dir / "out";
  ASSERT_EQ(runConfig(config, out, {"--seed", "1"}, dir.path()).exit_code, 0);
  RunResult r = runConfig(config, out, {"--seed", "2"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("--overwrite"), std::string::npos) << describe(r);
  EXPECT_EQ(readJson(out / "summary.json")["seed"].get<int>(), 1) << "the refused run changed the folder";
  r = runConfig(config, out, {"--seed", "2", "--overwrite"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_EQ(readJson(out / "summary.json")["seed"].get<int>(), 2);
  // A folder with unrelated files is fine and they are left alone.
  writeFile(dir / "mine" / "notes.txt", "keep");
  ASSERT_EQ(runConfig(config, dir / "mine", {}, dir.path()).exit_code, 0);
  EXPECT_EQ(readFile(dir / "mine" / "notes.txt"), "keep");
}

// --overwrite removed "exactly cortex's files" with remove_all: a folder named cortex.log
// went with everything in it, and --resume said "internal error" on one. Such a folder is
// refused (exit 2) and left alone; files of one's own in snapshots/ outlive an overwrite.
TEST(HostileInput, OverwriteRemovesOnlyWhatCortexWrote) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), kVesicle);
  const fs::path out = dir / "out";
  ASSERT_EQ(runConfig(config, out, {}, dir.path()).exit_code, 0);
  writeFile(out / "snapshots" / "notes.txt", "keep");
  ASSERT_EQ(runConfig(config, out, {"--overwrite"}, dir.path()).exit_code, 0);
  EXPECT_EQ(readFile(out / "snapshots" / "notes.txt"), "keep");

  fs::remove(out / "cortex.log");
  writeFile(out / "cortex.log" / "data.txt", "precious");
  for (const std::vector<std::string>& how :
       {std::vector<std::string>{"run", config.string(), "-o", out.string(), "--overwrite"},
        std::vector<std::string>{"run", "--resume", out.string()}}) {
    const RunResult r = runCortex(how, dir.path());
    EXPECT_EQ(r.exit_code, 2) << describe(r);
    EXPECT_NE(r.err.find("'cortex.log' is not the file cortex writes there"), std::string::npos) << describe(r);
    EXPECT_EQ(readFile(out / "cortex.log" / "data.txt"), "precious");
  }
}

// --resume continues in place, from the stored config: options it cannot honour are
// refused instead of ignored.
TEST(HostileInput, ResumeRefusesWhatItCannotHonour) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), kVesicle);
  const fs::path out = dir / "out";
  ASSERT_EQ(runConfig(config, out, {}, dir.path()).exit_code, 0);
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"-o", (dir / "other").string()}, std::vector<std::string>{"--overwrite"},
        std::vector<std::string>{"--set", "membrane.0.radius=300.0"},
        std::vector<std::string>{"--set", "simulation.seed=4"},
        // Membrane species' initial copies were ignored on resume (exit 0, the stored
        // copies unchanged); a footprint the stored copies overfill was taken.
        std::vector<std::string>{"--set", "membrane.0.species.0.copies=5000"},
        std::vector<std::string>{"--set", "membrane.0.species.0.footprint=1e6"}}) {
    std::vector<std::string> args{"run", "--resume", out.string(), "-q"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = runCortex(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << describe(r);
  }
  EXPECT_FALSE(fs::exists(dir / "other")) << "--resume -o created the other folder";
  // An error in an override names the stored config, not the original file's lines.
  const RunResult r =
      runCortex({"run", "--resume", out.string(), "-q", "--set", "membrane.0.bending_modulus=-1"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("config stored in"), std::string::npos) << describe(r);
}

// A resume continues snapshots 0 .. k - 1 of its checkpoint: with some of their files
// deleted it ended with exit 0 and a trajectory silently missing those times. Refused
// (exit 2) naming the first missing file; the folder is left as it was.
TEST(HostileInput, ResumeWithSnapshotsMissingIsRefused) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), kSpecies);
  const fs::path out = dir / "out";
  ASSERT_EQ(runConfig(config, out, {"--set", "simulation.end_time=0.01", "--set", "simulation.snapshot_interval=0.002"},
                      dir.path())
                .exit_code,
            0);
  fs::remove(out / "snapshots" / "000001.h5");
  const RunResult r = runCortex({"run", "--resume", out.string(), "--set", "simulation.end_time=0.02"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("snapshots/000001.h5"), std::string::npos) << describe(r);
  EXPECT_FALSE(fs::exists(out / "snapshots" / "000001.h5"));
}

// Without trajectory.h5 (which carries the run's id) resume cannot pair checkpoint and
// snapshots: it said "checkpoint.h5 belongs to another run than the missing
// trajectory.h5". It now says the file is missing, and that a damaged one is damaged.
TEST(HostileInput, ResumeWithoutItsTrajectoryIndexSaysItIsMissing) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), kSpecies);
  const fs::path out = dir / "out";
  ASSERT_EQ(runConfig(config, out, {"--set", "simulation.end_time=0.01"}, dir.path()).exit_code, 0);
  const auto resume = [&] {
    return runCortex({"run", "--resume", out.string(), "--set", "simulation.end_time=0.02"}, dir.path());
  };
  fs::rename(out / "trajectory.h5", dir / "moved.h5");
  RunResult r = resume();
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("trajectory.h5 is missing"), std::string::npos) << describe(r);
  EXPECT_EQ(r.err.find("another run"), std::string::npos) << describe(r);
  std::ofstream(out / "trajectory.h5") << "not HDF5";
  r = resume();
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("trajectory.h5 cannot be read"), std::string::npos) << describe(r);
  fs::rename(dir / "moved.h5", out / "trajectory.h5");
  EXPECT_EQ(resume().exit_code, 0);
}

}  // namespace
}  // namespace cortex::cli_test
