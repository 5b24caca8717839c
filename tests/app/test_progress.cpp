// Progress for batch jobs (issue 12): off a terminal, plain lines on stderr every
// --progress seconds, the last at 100%; a final line on stdout naming the output folder;
// none with --progress 0 or --quiet.
#include <gtest/gtest.h>

#include <sstream>

#include "app/cli_helpers.hpp"

namespace cortex::cli_test {
namespace {

constexpr const char* kConfig = R"([simulation]
seed = 1
end_time = 0.2
chemistry_window = 0.02
snapshot_interval = 0.1

[[membrane]]
name = "vesicle"
shape = "sphere"
radius = 200.0
mesh_size = 40.0
bending_modulus = 100.0
reduced_volume = [[0.0, 1.0], [0.2, 0.9]]
)";

std::vector<std::string> lines(const std::string& text, const std::string& prefix) {
  std::vector<std::string> found;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) found.push_back(line);
  return found;
}

TEST(Progress, PlainLinesOffATerminalAndAFinalLineNamingTheOutput) {
  const TempDir dir;
  const fs::path config = writeConfig(dir.path(), kConfig);
  const RunResult r = runCortex({"run", config.string(), "-o", (dir / "out").string(), "--progress", "0.000001"},
                                dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const std::vector<std::string> progress = lines(r.err, "cortex: t = ");
  ASSERT_GE(progress.size(), 10u) << r.err;  // one per window at least: the interval is tiny
  EXPECT_NE(progress.back().find("(100%)"), std::string::npos) << progress.back();
  EXPECT_NE(progress.back().find("mechanics"), std::string::npos) << progress.back();
  EXPECT_EQ(r.err.find('\r'), std::string::npos);  // no terminal refreshes in a file
  const std::vector<std::string> finished = lines(r.out, "cortex: finished");
  ASSERT_EQ(finished.size(), 1u) << r.out;
  EXPECT_NE(finished[0].find("results in " + (dir / "out").string()), std::string::npos) << finished[0];
}

TEST(Progress, NoneWithProgressZeroOrQuiet) {
  const TempDir dir;
  const fs::path config = writeConfig(dir.path(), kConfig);
  for (const std::vector<std::string>& quiet : {std::vector<std::string>{"--progress", "0"}, {"-q"}}) {
    std::vector<std::string> args{"run", config.string(), "-o", (dir / "out").string(), "--overwrite"};
    args.insert(args.end(), quiet.begin(), quiet.end());
    const RunResult r = runCortex(args, dir.path());
    ASSERT_EQ(r.exit_code, 0) << describe(r);
    EXPECT_TRUE(lines(r.err, "cortex: t = ").empty()) << r.err;
    EXPECT_EQ(lines(r.out, "cortex: finished").size(), 1u) << r.out;
  }
  const RunResult bad = runCortex({"run", config.string(), "-o", (dir / "bad").string(), "--progress", "-1"}, dir.path());
  EXPECT_EQ(bad.exit_code, 2) << describe(bad);
}

// The shares of wall time are this session's: a resumed run's counters carry the seconds
// spent before it, which once gave "mechanics 12259%" against the new session's wall time.
TEST(Progress, SharesOfAResumedRunAreThisSessions) {
  const TempDir dir;
  const fs::path config = writeConfig(dir.path(), kConfig);
  const fs::path out = dir / "out";
  ASSERT_EQ(runCortex({"run", config.string(), "-o", out.string(), "-q"}, dir.path()).exit_code, 0);
  const RunResult r = runCortex(
      {"run", "--resume", out.string(), "--set", "simulation.end_time=0.4", "--progress", "0.000001"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  int windows = 0;
  for (const std::string& line : lines(r.err, "cortex: t = ")) {
    const std::size_t at = line.find("mechanics ");
    if (at == std::string::npos) continue;  // a relaxation's line
    ++windows;
    const double percent = std::stod(line.substr(at + 10));
    EXPECT_GE(percent, 0.0) << line;
    EXPECT_LE(percent, 100.0) << line;
  }
  EXPECT_GE(windows, 10) << r.err;
  // The log's closing line of work done says its wall time is the session's.
  const std::string text = readFile(out / "cortex.log");
  const std::size_t last = text.rfind("mechanics: ");
  ASSERT_NE(last, std::string::npos) << text;
  EXPECT_NE(text.find("this session", last), std::string::npos) << text.substr(last);
}

}  // namespace
}  // namespace cortex::cli_test
