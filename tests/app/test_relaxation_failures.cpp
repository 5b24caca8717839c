// Issue 10: a relaxation that fails must never look like a result. Far from the force
// tolerance or folded, the run stops with exit code 1, a message naming the membrane, the
// time and the cause, and the last good snapshot kept.
#include <gtest/gtest.h>

#include <regex>

#include "app/cli_helpers.hpp"

namespace cortex::cli_test {
namespace {

// The issue's prolate case (radii 1000/1000/1748 nm, v 0.93 -> 0.9, stiff penalties),
// coarser, relaxed by CG over all coordinates: the line search gives up with forces of
// thousands of pN on a folded mesh. It used to exit 0 with 9.7 x 8 pi kappa.
TEST(RelaxationFailure, CgOnTheIssuesProlateExitsOneInsteadOfReportingAFoldedShape) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), R"([simulation]
end_time = 0.0
[mechanics]
minimizer = "cg"
force_tolerance = 0.001
[[membrane]]
name = "prolate"
shape = "ellipsoid"
radii = [1000.0, 1000.0, 1748.0]
mesh_size = 100.0
remesh = true
area_model = "global"
area_modulus = 2000.0
volume_modulus = 20.0
reduced_volume = 0.9
)");
  const RunResult r = runConfig(config, dir / "out", {"--threads", "1"}, dir.path());
  ASSERT_EQ(r.exit_code, 1) << describe(r);
  EXPECT_TRUE(std::regex_search(r.err, std::regex("far from equilibrium|folded"))) << describe(r);
  EXPECT_NE(r.err.find("t = 0 s"), std::string::npos) << describe(r);
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json")) << "a failed run must not write a summary";
}

// The default relaxation with too small an iteration budget for a shrink: the first
// window's relaxation ends far from the tolerance. The message names the membrane and
// the time; snapshot 0 and its checkpoint stay.
TEST(RelaxationFailure, DefaultRelaxationEndingFarFromToleranceExitsOneKeepingTheLastSnapshot) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), R"([simulation]
end_time = 0.1
chemistry_window = 0.02
snapshot_interval = 0.02
[mechanics]
max_iterations = 3
force_tolerance = 0.001
[[membrane]]
name = "shrinking"
shape = "sphere"
radius = 300.0
mesh_size = 40.0
remesh = true
reduced_volume = [[0.0, 1.0], [0.1, 0.7]]
)");
  const fs::path out = dir / "out";
  const RunResult r = runConfig(config, out, {"--threads", "1"}, dir.path());
  ASSERT_EQ(r.exit_code, 1) << describe(r);
  EXPECT_NE(r.err.find("membrane \"shrinking\""), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find("t = 0.02 s"), std::string::npos) << describe(r);
  EXPECT_NE(r.err.find("far from equilibrium"), std::string::npos) << describe(r);
  EXPECT_TRUE(fs::exists(out / "snapshots" / "000000.h5"));
  EXPECT_TRUE(fs::exists(out / "checkpoint.h5"));
  EXPECT_FALSE(fs::exists(out / "snapshots" / "000001.h5"));
}

// Under "lbfgs" the default force tolerance (0.1 pN) applies to membranes too; on this
// vesicle it is ~250 x the membrane's own force scale and the relaxation stopped 3.4%
// above the minimum energy, reported converged, without a word. It is said now; the
// default minimizer, which relaxes each membrane to its own scale, says nothing.
TEST(RelaxationFailure, TheDefaultToleranceFarAboveAMembranesScaleIsSaidUnderLbfgs) {
  TempDir dir;
  const std::string text = R"([simulation]
end_time = 0.0
[mechanics]
minimizer = "lbfgs"
[[membrane]]
name = "v"
shape = "ellipsoid"
radii = [400.0, 400.0, 650.0]
mesh_size = 30.0
bending_modulus = 60.0
reduced_volume = 0.85
volume_modulus = 0.01
)";
  const RunResult lbfgs = runConfig(writeConfig(dir.path(), text, "lbfgs.toml"), dir / "lbfgs", {}, dir.path());
  ASSERT_EQ(lbfgs.exit_code, 0) << describe(lbfgs);
  EXPECT_NE(lbfgs.err.find("(the default) is"), std::string::npos) << describe(lbfgs);
  std::string by_shape = text;
  by_shape.replace(by_shape.find("minimizer = \"lbfgs\""), 19, "minimizer = \"auto\"");
  const RunResult automatic = runConfig(writeConfig(dir.path(), by_shape, "auto.toml"), dir / "auto", {}, dir.path());
  ASSERT_EQ(automatic.exit_code, 0) << describe(automatic);
  EXPECT_EQ(automatic.err.find("its own force scale"), std::string::npos) << describe(automatic);
}

}  // namespace
}  // namespace cortex::cli_test
