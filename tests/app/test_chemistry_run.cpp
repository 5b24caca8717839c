// Chemistry through the whole program: config, loop, trajectory, summary, checkpoint.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <numeric>

#include "app/cli_helpers.hpp"
#include "io/hdf5_file.hpp"

namespace cortex::cli_test {
namespace {

// A <-> B in a 4 x 3 x 2 grid, plus inflow and decay of an immobile C produced only in
// the half x < 400 nm (a reaction region): copies of A + B are conserved exactly, and C
// exists only in that half.
std::string chemistryConfig(double end_time) {
  return fmt::format(R"([simulation]
seed = 5
end_time = {}
chemistry_window = 0.01
snapshot_interval = 0.05

[compartments]
size = 200.0
shape = [4, 3, 2]

[[species]]
name = "A"
diffusion = 1.0e5
copies = 3000

[[species]]
name = "B"
diffusion = 1.0e4
copies = 1000

[[species]]
name = "C"
diffusion = 0.0
copies = 0

[[reaction]]
equation = "A -> B"
rate = 20.0

[[reaction]]
equation = "B -> A"
rate = 10.0

[[reaction]]
equation = "-> C"
rate = 50.0
region = {{ min = [0.0, 0.0, 0.0], max = [400.0, 600.0, 400.0] }}

[[reaction]]
equation = "C ->"
rate = 2.0
)",
                     end_time);
}

std::int64_t sum(const std::vector<std::int32_t>& v) { return std::accumulate(v.begin(), v.end(), std::int64_t{0}); }

TEST(ChemistryRun, WritesCompartmentCountsAndConservesCopies) {
  TempDir dir;
  const fs::path out = dir / "out";
  const RunResult r = runConfig(writeConfig(dir.path(), chemistryConfig(0.2)), out, {"--threads", "1"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const h5::File f = h5::File::openReadOnly(out / "trajectory.h5");
  const std::vector<std::string> snapshots = f.children("/snapshots");
  ASSERT_EQ(snapshots.size(), 5u);  // t = 0, 0.05, ..., 0.2
  for (const std::string& s : snapshots) {
    h5::Shape shape;
    const auto a = f.readInt32("/snapshots/" + s + "/compartments/species/A", &shape);
    const auto b = f.readInt32("/snapshots/" + s + "/compartments/species/B");
    EXPECT_EQ(shape, (h5::Shape{4, 3, 2}));
    EXPECT_EQ(sum(a) + sum(b), 4000) << "snapshot " << s << ": A <-> B must conserve A + B";
  }
  // C: immobile, produced only where x < 400 nm; in the (4, 3, 2) C-order array x is the first index.
  const auto c_last = f.readInt32("/snapshots/" + snapshots.back() + "/compartments/species/C");
  std::int64_t inside = 0, outside = 0;
  for (std::size_t n = 0; n < c_last.size(); ++n) (n / 6 < 2 ? inside : outside) += c_last[n];
  EXPECT_GT(inside, 10);
  EXPECT_EQ(outside, 0) << "the region restricts -> C to x < 400 nm";
  const nlohmann::json summary = readJson(out / "summary.json");
  const std::string last = "/snapshots/" + snapshots.back() + "/compartments/species/";
  for (const char* species : {"A", "B", "C"})
    EXPECT_EQ(summary["chemistry"]["species"][species].get<std::int64_t>(), sum(f.readInt32(last + species)));
  EXPECT_GT(summary["chemistry"]["events"].get<std::int64_t>(), 1000);
  std::int64_t by_reaction = 0;
  for (const auto& reaction : summary["chemistry"]["reactions"]) by_reaction += reaction["events"].get<std::int64_t>();
  EXPECT_EQ(by_reaction + summary["chemistry"]["diffusion_events"].get<std::int64_t>(),
            summary["chemistry"]["events"].get<std::int64_t>());
  EXPECT_NE(readFile(out / "cortex.log").find("events/s"), std::string::npos);
}

TEST(ChemistryRun, ResumesBitIdentically) {
  TempDir dir;
  runWholeAndResumed(dir, chemistryConfig, 0.1, 0.2);
  if (::testing::Test::HasFatalFailure()) return;
  EXPECT_EQ(comparableSummary(dir / "A"), comparableSummary(dir / "B"));
  expectSameCompartmentCounts(dir / "A" / "trajectory.h5", dir / "B" / "trajectory.h5", {"A", "B", "C"});
}

TEST(ChemistryRun, BadReactionNamesTheKey) {
  TempDir dir;
  std::string text = chemistryConfig(0.1);
  text.replace(text.find("A -> B"), 6, "A -> Q");
  const RunResult r = runCortex({"check", writeConfig(dir.path(), text).string()}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("reaction.0.equation"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Q"), std::string::npos) << r.err;
}

// A reaction of an unconfined species restricted to the inside of a vesicle: its
// product (immobile) appears only in compartments that overlap the inside.
TEST(ChemistryRun, ReactionRestrictedToInsideOfAMembrane) {
  TempDir dir;
  const std::string config = R"([simulation]
end_time = 0.1
chemistry_window = 0.05
snapshot_interval = 0.05

[compartments]
size = 200.0
shape = [4, 4, 4]

[[membrane]]
name = "vesicle"
shape = "sphere"
mesher = "icosphere"
center = [400.0, 400.0, 400.0]
radius = 300.0
mesh_size = 40.0

[[species]]
name = "C"
diffusion = 0.0
copies = 0

[[reaction]]
equation = "-> C"
rate = 20.0
inside = "vesicle"
)";
  const fs::path out = dir / "out";
  const RunResult r = runConfig(writeConfig(dir.path(), config), out, {}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const h5::File f = h5::File::openReadOnly(out / "trajectory.h5");
  const auto c = f.readInt32("/snapshots/" + f.children("/snapshots").back() + "/compartments/species/C");
  ASSERT_EQ(c.size(), 64u);
  // The eight corner cubes lie wholly outside the sphere (their nearest point is 346 nm
  // from the centre, beyond the radius 300 nm).
  for (int i : {0, 3})
    for (int j : {0, 3})
      for (int k : {0, 3}) EXPECT_EQ(c[(i * 4 + j) * 4 + k], 0) << "corner " << i << j << k;
  EXPECT_GT(sum(c), 50);
}

}  // namespace
}  // namespace cortex::cli_test
