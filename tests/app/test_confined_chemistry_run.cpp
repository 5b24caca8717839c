// Membrane-confined chemistry through the whole program: a vesicle with one species
// inside and one outside; config errors; resume bit-identical (the confinement is
// recomputed from the restored membrane, nothing is stored for it).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numeric>

#include "app/cli_helpers.hpp"
#include "io/hdf5_file.hpp"

namespace cortex::cli_test {
namespace {

constexpr double kH = 250.0, kRadius = 500.0, kCentre = 750.0;  // nm; 6 x 6 x 6 grid

std::string confinedConfig(double end_time) {
  return fmt::format(R"([simulation]
seed = 3
end_time = {}
chemistry_window = 0.01
snapshot_interval = 0.02

[mechanics]
minimizer = "lbfgs"
force_tolerance = 0.5

[[membrane]]
name = "vesicle"
shape = "sphere"
center = [{c}, {c}, {c}]
radius = {r}
mesh_size = 80.0
bending_modulus = 100.0
area_modulus = 400.0
volume_modulus = 0.8
reduced_volume = 1.0

[compartments]
size = {h}
shape = [6, 6, 6]

[[species]]
name = "A"
diffusion = 1.0e6
copies = 2000
inside = "vesicle"

[[species]]
name = "B"
diffusion = 1.0e5
copies = 0
inside = "vesicle"

[[species]]
name = "C"
diffusion = 1.0e6
copies = 1000
outside = "vesicle"

[[reaction]]
equation = "2 A -> B"
rate = 0.05

[[reaction]]
equation = "B -> 2 A"
rate = 2.0
)",
                     end_time, fmt::arg("c", kCentre), fmt::arg("r", kRadius), fmt::arg("h", kH));
}

std::int64_t sum(const std::vector<std::int32_t>& v) { return std::accumulate(v.begin(), v.end(), std::int64_t{0}); }

// Distances from the vesicle centre to the nearest and farthest points of a compartment.
std::pair<double, double> reach(int i, int j, int k) {
  double near = 0.0, far = 0.0;
  for (int x : {i, j, k}) {
    const double lo = x * kH - kCentre, hi = (x + 1) * kH - kCentre;
    const double n = lo > 0 ? lo : hi < 0 ? -hi : 0.0, f = std::max(std::abs(lo), std::abs(hi));
    near += n * n;
    far += f * f;
  }
  return {std::sqrt(near), std::sqrt(far)};
}

// The vesicle stays a sphere of radius ~500 nm (reduced volume 1): compartments well
// beyond it never hold A or B, compartments well within it never hold C, and A + 2 B
// and C are conserved.
TEST(ConfinedChemistryRun, SpeciesStayOnTheirSide) {
  TempDir dir;
  const fs::path out = dir / "out";
  const RunResult r = runConfig(writeConfig(dir.path(), confinedConfig(0.1)), out, {"--threads", "2"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const h5::File f = h5::File::openReadOnly(out / "trajectory.h5");
  const std::vector<std::string> snapshots = f.children("/snapshots");
  ASSERT_EQ(snapshots.size(), 6u);
  int checked_outside = 0, checked_inside = 0;
  for (const std::string& s : snapshots) {
    const std::string g = "/snapshots/" + s + "/compartments/species/";
    const auto a = f.readInt32(g + "A"), b = f.readInt32(g + "B"), c = f.readInt32(g + "C");
    EXPECT_EQ(sum(a) + 2 * sum(b), 2000) << s;
    EXPECT_EQ(sum(c), 1000) << s;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        for (int k = 0; k < 6; ++k) {
          const std::size_t n = static_cast<std::size_t>((i * 6 + j) * 6 + k);  // datasets are [x][y][z]
          const auto [near, far] = reach(i, j, k);
          if (near > 1.04 * kRadius) {
            EXPECT_EQ(a[n] + b[n], 0) << s << " compartment " << i << j << k;
            ++checked_outside;
          }
          if (far < 0.9 * kRadius) {
            EXPECT_EQ(c[n], 0) << s << " compartment " << i << j << k;
            ++checked_inside;
          }
        }
  }
  EXPECT_GT(checked_outside, 0);
  EXPECT_GT(checked_inside, 0);
}

TEST(ConfinedChemistryRun, ResumesBitIdentically) {
  TempDir dir;
  runWholeAndResumed(dir, confinedConfig, 0.02, 0.06);
  if (::testing::Test::HasFatalFailure()) return;
  EXPECT_EQ(comparableSummary(dir / "A"), comparableSummary(dir / "B"));
  expectSameCompartmentCounts(dir / "A" / "trajectory.h5", dir / "B" / "trajectory.h5", {"A", "B", "C"});
}

TEST(ConfinedChemistryRun, BadConfinementNamesTheKey) {
  std::string unknown = confinedConfig(0.1);
  unknown.replace(unknown.find("inside = \"vesicle\""), 18, "inside = \"cell\"");
  expectCheckFails(unknown, "species.0.inside", "cell");

  std::string both = confinedConfig(0.1);
  both.replace(both.find("inside = \"vesicle\""), 18, "inside = \"vesicle\"\noutside = \"vesicle\"");
  expectCheckFails(both, "species.0.outside", "not both");

  std::string concentration = confinedConfig(0.1);
  concentration.replace(concentration.find("copies = 2000"), 13, "concentration = 1.0");
  expectCheckFails(concentration, "species.0.concentration", "confined");

  std::string mixed = confinedConfig(0.1);
  mixed.replace(mixed.find("2 A -> B"), 8, "A + C -> B");
  expectCheckFails(mixed, "reaction.0.equation", "different sides");

  const std::string open = R"([[membrane]]
name = "sheet"
shape = "plane"
size = [1000.0, 1000.0]
mesh_size = 100.0
bending_modulus = 100.0

[[species]]
name = "A"
diffusion = 1.0e6
copies = 10
outside = "sheet"
)";
  expectCheckFails(open, "species.0.outside", "open");
}

// Proteins on one vesicle unbinding into a species confined by another vesicle: only
// vertices on the species' side can react. Side by side, the proteins' vesicle never
// touches the inside of the other, and the reaction (which fired 0 times, exit 0) is
// refused by name. Nested, the inner vesicle lies inside the outer one: accepted, and it
// fires; the same with the species outside the outer vesicle is refused again. Vesicles
// that cut each other are refused, whatever their species.
TEST(ConfinedChemistryRun, AMembraneReactionWithASideItsMembraneNeverTouchesIsRefused) {
  const auto twoVesicles = [](double x2, double r2, const char* side) {
    return fmt::format(R"([simulation]
seed = 1
end_time = 0.02
chemistry_window = 0.01
snapshot_interval = 0.01

[[membrane]]
name = "v1"
shape = "sphere"
center = [700.0, 1500.0, 1500.0]
radius = 500.0
mesh_size = 100.0
bending_modulus = 100.0

[[membrane]]
name = "v2"
shape = "sphere"
center = [{}, 1500.0, 1500.0]
radius = {}
mesh_size = 60.0
bending_modulus = 100.0

[[membrane.species]]
name = "N"
diffusion = 1.0e5
copies = 1000

[compartments]
size = 250.0
shape = [12, 12, 12]

[[species]]
name = "G"
diffusion = 1.0e6
copies = 100
{} = "v1"

[[reaction]]
equation = "N -> G"
rate = 10.0
)",
                       x2, r2, side);
  };
  expectCheckFails(twoVesicles(2300.0, 500.0, "inside"), "reaction.0.equation",
                   "no vertex of \"v2\" lies inside \"v1\": the reaction could never fire");
  expectCheckFails(twoVesicles(700.0, 250.0, "outside"), "reaction.0.equation",
                   "no vertex of \"v2\" lies outside \"v1\"");
  // Vesicles that pass through each other overlapped their insides all run long (exit 0).
  expectCheckFails(twoVesicles(1100.0, 500.0, "inside"), "membranes \"v1\" and \"v2\" pass through each other",
                   "must start apart");
  // Proteins on a vesicle outside the grid reacted with the compartment nearest to it.
  std::string far = twoVesicles(2300.0, 500.0, "inside");
  far.replace(far.find("center = [2300,"), 15, "center = [9.0e4,");
  expectCheckFails(far, "reaction.0.equation", "vertices of \"v2\" lie outside the compartment grid");
  // Species inside a vesicle partly outside the grid would crowd into the part within it.
  std::string inside_beyond = confinedConfig(0.1);
  inside_beyond.replace(inside_beyond.find("center = [750, 750, 750]"), 24, "center = [750, 750, 1200]");
  expectCheckFails(inside_beyond, "[[species]] \"A\" inside = \"vesicle\"", "lie outside the compartment grid");
  // Partly outside (x up to 3200 nm in a 3000 nm grid): its cap beyond the grid bound into
  // the grid's edge while the volume there held nothing, an equilibrium 18% off (exit 0).
  std::string partly = twoVesicles(2300.0, 500.0, "inside");
  partly.replace(partly.find("center = [2300,"), 15, "center = [2700,");
  expectCheckFails(partly, "reaction.0.equation", "lie outside the compartment grid");
  TempDir dir;
  const RunResult nested =
      runCortex({"run", writeConfig(dir.path(), twoVesicles(700.0, 250.0, "inside")).string(), "-o",
                 (dir.path() / "out").string()},
                dir.path());
  ASSERT_EQ(nested.exit_code, 0) << describe(nested);
  // 1000 copies at 10/s for 0.02 s: about 180 unbind (1000 (1 − e^{−0.2})).
  EXPECT_GT(readJson(dir.path() / "out" / "summary.json")["chemistry"]["reactions"][0]["events"].get<int>(), 100);
}

// A vesicle under two compartments across is sliced with errors of several percent in
// its volume (CompartmentSlicing.TheVolumeErrorGrowsAsTheVesicleShrinksToACompartment):
// check accepts it but says so, naming the membrane and the key that fixes it. The
// vesicle of the tests above, four compartments across, gets no warning; under one
// compartment across the config is refused.
TEST(ConfinedChemistryRun, AVesicleFewCompartmentsAcrossIsWarnedOf) {
  TempDir dir;
  const auto check = [&](const std::string& text) {
    const fs::path config = dir.path() / "coarse.toml";
    std::ofstream(config) << text;
    return runCortex({"check", config.string()}, dir.path());
  };
  const RunResult fine = check(confinedConfig(0.1));
  EXPECT_EQ(fine.exit_code, 0) << describe(fine);
  EXPECT_EQ(fine.err.find("compartments across"), std::string::npos) << describe(fine);
  std::string coarse = confinedConfig(0.1);
  coarse.replace(coarse.find("size = 250"), 10, "size = 600");  // 1000 nm across: 1.7 compartments
  const RunResult warned = check(coarse);
  EXPECT_EQ(warned.exit_code, 0) << describe(warned);
  EXPECT_NE(warned.err.find("membrane \"vesicle\" confines species but is only 1.7 compartments across"),
            std::string::npos)
      << describe(warned);
  EXPECT_NE(warned.err.find("[compartments] size"), std::string::npos) << describe(warned);
  // Under one compartment across (10-50% of the volume missed) it is an input error.
  std::string too_coarse = confinedConfig(0.1);
  too_coarse.replace(too_coarse.find("size = 250"), 10, "size = 1100");
  expectCheckFails(too_coarse, "vesicle", "0.91 compartments across");
}

// The grid checks hold through the run, not only at the start: a vesicle whose area
// doubles over 0.05 s (R 400 -> 566 nm) grows past the grid's wall at x = 1500 nm after
// t = 0.02 s: 0.6% of its area is beyond it at t = 0.03 s (tolerated, under 1%), 3.6% at
// 0.04 s. Before, its proteins bound into the grid's edge from that area and the species
// inside it crowded into the part within the grid, exit 0. Now exit 1 at t = 0.04 s,
// naming what needs the grid, the snapshots before kept; in a grid wide enough the same
// run finishes.
TEST(ConfinedChemistryRun, AMembraneGrowingOutOfTheGridStopsTheRun) {
  TempDir dir;
  const std::string text = R"([simulation]
seed = 2
end_time = 0.06
chemistry_window = 0.01
snapshot_interval = 0.01

[[membrane]]
name = "v"
shape = "sphere"
center = [1000.0, 750.0, 750.0]
radius = 400.0
mesh_size = 80.0
bending_modulus = 100.0
target_area = [[0.0, 2.0106e6], [0.05, 4.0212e6]]

[[membrane.species]]
name = "N"
diffusion = 1.0e5
copies = 200

[compartments]
size = 250.0
shape = [6, 6, 6]

[[species]]
name = "G"
diffusion = 1.0e6
copies = 1000
inside = "v"

[[reaction]]
equation = "N -> G"
rate = 10.0
[[reaction]]
equation = "G -> N"
rate = 100.0
)";
  const auto run = [&](const std::string& config_text, const std::string& name) {
    return runCortex({"run", writeConfig(dir.path(), config_text, name + ".toml").string(), "-o",
                      (dir.path() / name).string()},
                     dir.path());
  };
  // G free in the grid: the proteins' binding needs the membrane within it.
  std::string free = text;
  free.erase(free.find("inside = \"v\"\n"), 13);
  const RunResult grown = run(free, "grown");
  EXPECT_EQ(grown.exit_code, 1) << describe(grown);
  EXPECT_NE(grown.err.find("t = 0.04 s: membrane \"v\": "), std::string::npos) << describe(grown);
  EXPECT_NE(grown.err.find("% of its area, over the 1% a run tolerates) moved outside the compartment grid"), std::string::npos) << describe(grown);
  EXPECT_NE(grown.err.find("(reaction.0.equation)"), std::string::npos) << describe(grown);
  EXPECT_TRUE(fs::exists(dir.path() / "grown" / "snapshots" / "000003.h5")) << describe(grown);
  // G inside the vesicle: its inside must stay within the grid (checked first).
  const RunResult confined = run(text, "confined");
  EXPECT_EQ(confined.exit_code, 1) << describe(confined);
  EXPECT_NE(confined.err.find("t = 0.04 s, after the relaxation: [[species]] \"G\" inside = \"v\": "),
            std::string::npos)
      << describe(confined);
  EXPECT_NE(confined.err.find("lie outside the compartment grid"), std::string::npos) << describe(confined);
  std::string wide = text;
  wide.replace(wide.find("shape = [6, 6, 6]"), 17, "shape = [8, 6, 6]");
  const RunResult inside = run(wide, "wide");
  EXPECT_EQ(inside.exit_code, 0) << describe(inside);
}

TEST(ConfinedChemistryRun, ExampleIsAccepted) {
  TempDir dir;
  const RunResult r =
      runCortex({"check", (sourceDir() / "examples" / "vesicle_confined_species.toml").string()}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << describe(r);
}

}  // namespace
}  // namespace cortex::cli_test
