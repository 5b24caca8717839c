// What a sweep file says: members enumerated in a fixed order (grid row-major in the
// order the keys are written, seeds innermost), their overrides as `--set` reads them,
// and bad sweep files refused with the file, line, key and problem named.
#include <gtest/gtest.h>

#include "app/cli_helpers.hpp"
#include "core/error.hpp"
#include "sweep/sweep_spec.hpp"

namespace cortex {
namespace {

using cli_test::TempDir;
using cli_test::writeConfig;

SweepSpec read(const TempDir& dir, const std::string& text) {
  return readSweepFile(writeConfig(dir.path(), text, "sweep.toml"));
}

// The InputError message readSweepFile throws for `text`.
std::string refusal(const std::string& text) {
  TempDir dir;
  try {
    read(dir, text);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return "";
}

TEST(SweepSpec, GridIsRowMajorInTheOrderWrittenWithSeedsInnermost) {
  TempDir dir;
  // "z" before "a": the written order, not the alphabetical one, decides.
  const SweepSpec spec = read(dir, R"(base = "run.toml"
seeds = 2
[grid]
"z.kappa" = [10.0, 20.0, 30.0]
"a.end_time" = [0.5, 1]
)");
  EXPECT_EQ(spec.base, dir.path() / "run.toml");
  EXPECT_EQ(spec.keys, (std::vector<std::string>{"z.kappa", "a.end_time"}));
  ASSERT_EQ(spec.members.size(), 12u);
  EXPECT_EQ(memberOverrides(spec, spec.members[0]),
            (std::vector<std::string>{"z.kappa=10.0", "a.end_time=0.5", "simulation.seed=1"}));
  EXPECT_EQ(memberOverrides(spec, spec.members[1]),
            (std::vector<std::string>{"z.kappa=10.0", "a.end_time=0.5", "simulation.seed=2"}));
  EXPECT_EQ(memberOverrides(spec, spec.members[3]),
            (std::vector<std::string>{"z.kappa=10.0", "a.end_time=1", "simulation.seed=2"}));
  EXPECT_EQ(memberOverrides(spec, spec.members[11]),
            (std::vector<std::string>{"z.kappa=30.0", "a.end_time=1", "simulation.seed=2"}));
  EXPECT_EQ(*spec.members[4].values[0]->number, 20.0);
  EXPECT_EQ(memberFolder(spec, 7), std::filesystem::path("members/0007"));
}

TEST(SweepSpec, NestedTablesNameTheSameKeysAsQuotedPaths) {
  TempDir dir;
  const SweepSpec spec = read(dir, R"(base = "run.toml"
[grid.membrane.0]
bending_modulus = [1.0, 2.0]
)");
  EXPECT_EQ(spec.keys, (std::vector<std::string>{"membrane.0.bending_modulus"}));
  EXPECT_EQ(spec.members.size(), 2u);
  EXPECT_FALSE(spec.members[0].seed) << "without seeds the base config's seed applies";
}

// Strings are written as toml++ writes them: a literal string when that needs no escapes.
TEST(SweepSpec, ValuesKeepTheirTomlKindAndStringsAreQuoted) {
  TempDir dir;
  const SweepSpec spec = read(dir, R"(base = "run.toml"
seeds = [7, 3]
[grid]
"a.count" = [5]
"a.x" = [1e-5, 2.5e300]
"a.flag" = [true]
"a.name" = ["say \"hi\""]
)");
  ASSERT_EQ(spec.members.size(), 4u);
  EXPECT_EQ(memberOverrides(spec, spec.members[3]),
            (std::vector<std::string>{"a.count=5", "a.x=2.5e+300", "a.flag=true", R"(a.name='say "hi"')",
                                      "simulation.seed=3"}));
  EXPECT_EQ(spec.key_is_string, (std::vector<bool>{false, false, false, true}));
  EXPECT_EQ(*spec.members[0].values[2]->number, 1.0);
  EXPECT_EQ(spec.members[0].values[3]->text, "say \"hi\"");
}

TEST(SweepSpec, ExplicitMembersMayLeaveKeysOut) {
  TempDir dir;
  const SweepSpec spec = read(dir, R"(base = "run.toml"
parallel = 3
[[members]]
"a.x" = 1.0
[[members]]
"b.y" = "fast"
"a.x" = 2.0
)");
  EXPECT_EQ(spec.parallel, 3);
  EXPECT_EQ(spec.keys, (std::vector<std::string>{"a.x", "b.y"}));
  ASSERT_EQ(spec.members.size(), 2u);
  EXPECT_EQ(memberOverrides(spec, spec.members[0]), (std::vector<std::string>{"a.x=1.0"}));
  EXPECT_FALSE(spec.members[0].values[1]);
  EXPECT_EQ(memberOverrides(spec, spec.members[1]), (std::vector<std::string>{"a.x=2.0", "b.y='fast'"}));
}

TEST(SweepSpec, AnArrayOfNumbersIsOneValue) {
  // A vector key (a bundle's direction) swept as a whole, in a grid and in members; the
  // sweep table records it as its TOML text.
  TempDir dir;
  const SweepSpec grid = read(dir, R"(base = "run.toml"
[grid]
"filaments.0.direction" = [[0, 0, 1], [0.5, 0.0, 0.866]]
)");
  ASSERT_EQ(grid.members.size(), 2u);
  EXPECT_EQ(grid.key_is_string, (std::vector<bool>{true}));
  EXPECT_EQ(memberOverrides(grid, grid.members[0]), (std::vector<std::string>{"filaments.0.direction=[0, 0, 1]"}));
  EXPECT_EQ(memberOverrides(grid, grid.members[1]),
            (std::vector<std::string>{"filaments.0.direction=[0.5, 0.0, 0.866]"}));
  EXPECT_EQ(grid.members[1].values[0]->text, "[0.5, 0.0, 0.866]");
  const SweepSpec listed = read(dir, R"(base = "run.toml"
[[members]]
"a.v" = [1.0, 2.0]
"a.x" = 3.0
)");
  EXPECT_EQ(memberOverrides(listed, listed.members[0]), (std::vector<std::string>{"a.v=[1.0, 2.0]", "a.x=3.0"}));
}

TEST(SweepSpec, RecognisesASweepFileByItsBaseKey) {
  TempDir dir;
  EXPECT_TRUE(isSweepFile(writeConfig(dir.path(), "base = \"x.toml\"\nseeds = 2\n", "s.toml")));
  EXPECT_FALSE(isSweepFile(writeConfig(dir.path(), "[simulation]\nend_time = 0.0\n", "r.toml")));
  EXPECT_FALSE(isSweepFile(writeConfig(dir.path(), "base = \n", "broken.toml")));
  EXPECT_FALSE(isSweepFile(dir / "missing.toml"));
}

TEST(SweepSpec, BadSweepFilesNameFileLineKeyAndProblem) {
  const auto expect = [](const std::string& text, const std::vector<std::string>& needles) {
    const std::string message = refusal(text);
    EXPECT_NE(message.find("sweep.toml"), std::string::npos) << message;
    for (const std::string& n : needles) EXPECT_NE(message.find(n), std::string::npos) << n << " in: " << message;
  };
  expect("seeds = 2\n", {"base", "required"});
  expect("base = \"r.toml\"\n", {"nothing to sweep"});
  expect("base = \"r.toml\"\nseed = 2\n", {":2:", "seed", "unknown key"});
  expect("base = \"r.toml\"\nseeds = 0\n", {"seeds", "[1, 100000]"});
  expect("base = \"r.toml\"\nseeds = [1, 1]\n", {"seed 1 is listed twice"});
  expect("base = \"r.toml\"\nseeds = [-1]\n", {"seeds", "integer in [0,"});
  expect("base = \"r.toml\"\nparallel = 0\n", {"parallel", "[1, 4096]"});
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = []\n", {":3:", "grid.a.x", "non-empty list"});
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = 1.0\n", {"grid.a.x", "non-empty list"});
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = [1.0, \"b\"]\n", {"grid.a.x", "mixes strings"});
  // One key as a dotted key and in a table: the second was dropped without a word.
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = [1.0]\n[grid.a]\nx = [2.0]\n", {":5:", "grid.a.x", "given twice"});
  // A value listed twice made identical members (1001 copies of one run were checked
  // for 100 s); 1 and 1.0 are one value.
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = [0.9, 0.8, 0.9]\n", {":3:", "grid.a.x", "lists 0.9 twice"});
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = [1, 1.0]\n", {"grid.a.x", "lists 1.0 twice"});
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = [\"u\", \"u\"]\n", {"grid.a.x", "twice"});
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = [[1.0, 0.0], [1.0, 0.0]]\n", {"grid.a.x", "twice"});
  expect("base = \"r.toml\"\n[[members]]\n\"a\" = 1\n[[members]]\n\"b\" = 2\n[[members]]\n\"a\" = 1.0\n",
         {"members.2", "same run"});
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = [{ b = 1 }]\n", {"grid.a.x", "an array of numbers"});
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = [[1.0, \"b\"]]\n", {"grid.a.x", "numbers only"});
  expect("base = \"r.toml\"\n[grid]\n\"a.x\" = [[]]\n", {"grid.a.x", "at least one number"});
  expect("base = \"r.toml\"\n[grid]\n\"a..x\" = [1.0]\n", {"a..x", "not a key path"});
  expect("base = \"r.toml\"\nseeds = 2\n[grid]\n\"simulation.seed\" = [1]\n", {"simulation.seed", "seeds"});
  expect("base = \"r.toml\"\n[grid]\n\"a\" = [1]\n[[members]]\n\"a\" = 1\n", {"members", "not both"});
  expect("base = \"r.toml\"\n[[members]]\n\"a\" = [1, [2]]\n", {"members.0.a", "numbers only"});
  expect("base = \"r.toml\"\n[[members]]\n\"a\" = 1\n[[members]]\n\"a\" = \"x\"\n", {"a", "mixes strings"});
  expect("base = \"r.toml\"\n[grid]\n\"a\" = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n\"b\" = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n"
         "\"c\" = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n\"d\" = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n"
         "\"e\" = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n\"f\" = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n"
         "\"g\" = [1, 2]\n",
         {"grid", "more than 1000000"});
  expect("base = \"r.toml\"\n[grid\n", {"invalid TOML"});
}

}  // namespace
}  // namespace cortex
