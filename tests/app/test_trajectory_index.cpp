// The trajectory index (trajectory.h5, observables.csv, trajectory.xdmf) is rewritten
// less often once a run has written 100 snapshots (io/trajectory_writer.hpp): 2,000
// snapshots of a small run took 29 s and 4,000 over two minutes when it was rewritten
// after each. Whatever it skipped, a run that finishes or fails lists every snapshot file
// it wrote, with one observables row each.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "app/cli_helpers.hpp"
#include "io/hdf5_file.hpp"
#include "test_text.hpp"

namespace cortex::cli_test {
namespace {

using cortex::testing::countOccurrences;

// One 500 nm compartment of A with a window and a snapshot every 0.1 ms; `extra` adds a
// reaction.
std::string manySnapshots(const std::string& extra) {
  return R"([simulation]
end_time = 0.03
chemistry_window = 1e-4
snapshot_interval = 1e-4
checkpoint_interval = 1.0
[compartments]
size = 500.0
shape = [1, 1, 1]
[[species]]
name = "A"
diffusion = 1.0e6
copies = 10
[[species]]
name = "B"
)" + extra;
}

std::size_t filesIn(const fs::path& folder) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder)) ++n;
  return n;
}

void expectEverySnapshotListed(const fs::path& out, std::size_t at_least) {
  const std::size_t files = filesIn(out / "snapshots");
  EXPECT_GT(files, at_least);
  EXPECT_EQ(h5::File::openReadOnly(out / "trajectory.h5").children("/snapshots").size(), files);
  std::ifstream csv(out / "observables.csv");
  std::size_t lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, files + 1);  // and the header
  EXPECT_EQ(countOccurrences(readFile(out / "trajectory.xdmf"), "<Time Value="), files);
}

TEST(TrajectoryIndex, AFinishedRunListsEverySnapshot) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), manySnapshots(""), "many.toml");
  const RunResult r = runConfig(config, dir / "out", {}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  expectEverySnapshotListed(dir / "out", 300);
}

// Each event adds 999,999 copies of B: the copy number overflows near t = 0.02 s, after
// ~200 snapshots (exit 1).
TEST(TrajectoryIndex, AFailedRunListsEverySnapshotItWrote) {
  TempDir dir;
  const fs::path config = writeConfig(
      dir.path(), manySnapshots("[[reaction]]\nequation = \"A -> A + 999999 B\"\nrate = 1.0e4\n"), "failing.toml");
  const RunResult r = runConfig(config, dir / "out", {}, dir.path());
  ASSERT_EQ(r.exit_code, 1) << describe(r);
  expectEverySnapshotListed(dir / "out", 100);
}

}  // namespace
}  // namespace cortex::cli_test
