// [membrane_filament]: on with its defaults whenever a config has membranes and
// filaments; its keys typed and checked; an error without one of the two, and refused
// values named by their dotted key.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/config.hpp"

namespace cortex {
namespace {

const std::string kMembrane = R"(
[[membrane]]
name = "patch"
shape = "plane"
center = [250.0, 250.0, 250.0]
size = [400.0, 400.0]
mesh_size = 40.0
)";

const std::string kFilaments = R"(
[[filament_type]]
name = "actin"

[[filaments]]
count = 2
length = 54.0
placement = "bundle"
center = [250.0, 250.0, 150.0]
direction = [0.0, 0.0, 1.0]
)";

Config parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return parseConfig(text, "test.toml", ".", overrides);
}

std::string errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse(text, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MembraneFilamentConfig, OnByDefaultWithBothAndAbsentOtherwise) {
  const Config both = parse(kMembrane + kFilaments);
  ASSERT_TRUE(both.membrane_filament);
  EXPECT_EQ(both.membrane_filament->stiffness, 100.0);
  EXPECT_EQ(both.membrane_filament->cutoff, 20.0);
  EXPECT_EQ(both.membrane_filament->beads, ExclusionBeads::kAll);
  EXPECT_FALSE(parse(kMembrane).membrane_filament);
  EXPECT_FALSE(parse(kFilaments).membrane_filament);
}

TEST(MembraneFilamentConfig, KeysAreReadAndCanTurnItOff) {
  const Config c = parse(kMembrane + kFilaments +
                         "[membrane_filament]\nstiffness = 40.0\ncutoff = 12.5\nbeads = \"plus_ends\"\n");
  ASSERT_TRUE(c.membrane_filament);
  EXPECT_EQ(c.membrane_filament->stiffness, 40.0);
  EXPECT_EQ(c.membrane_filament->cutoff, 12.5);
  EXPECT_EQ(c.membrane_filament->beads, ExclusionBeads::kPlusEnds);
  EXPECT_EQ(parse(kMembrane + kFilaments + "[membrane_filament]\nbeads = \"ends\"\n").membrane_filament->beads,
            ExclusionBeads::kEnds);
  EXPECT_FALSE(parse(kMembrane + kFilaments + "[membrane_filament]\nenabled = false\n").membrane_filament);
}

TEST(MembraneFilamentConfig, BadValuesAreNamed) {
  const std::string base = kMembrane + kFilaments + "[membrane_filament]\n";
  EXPECT_NE(errorOf(base + "stiffness = 0.0\n").find("membrane_filament.stiffness"), std::string::npos);
  EXPECT_NE(errorOf(base + "cutoff = -1.0\n").find("membrane_filament.cutoff"), std::string::npos);
  EXPECT_NE(errorOf(base + "cutoff = nan\n").find("membrane_filament.cutoff"), std::string::npos);
  EXPECT_NE(errorOf(base + "beads = \"tips\"\n").find("membrane_filament.beads"), std::string::npos);
  EXPECT_NE(errorOf(base + "stifness = 3.0\n").find("membrane_filament.stifness"), std::string::npos);
  const std::string alone = errorOf(kMembrane + "[membrane_filament]\nstiffness = 3.0\n");
  EXPECT_NE(alone.find("membrane_filament"), std::string::npos) << alone;
  EXPECT_NE(alone.find("needs at least one [[membrane]] and a [[filament_type]]"), std::string::npos) << alone;
}

// [mechanics] filament_minimizer: conjugate gradients unless asked, and only under "auto".
TEST(MembraneFilamentConfig, FilamentMinimizerIsCgUnlessAskedAndOnlyUnderAuto) {
  EXPECT_FALSE(parse(kMembrane + kFilaments).mechanics.precondition_filaments);
  EXPECT_TRUE(parse(kMembrane + kFilaments + "[mechanics]\nfilament_minimizer = \"preconditioned_lbfgs\"\n")
                  .mechanics.precondition_filaments);
  const std::string wrong = errorOf(kMembrane + kFilaments +
                                    "[mechanics]\nminimizer = \"cg\"\nfilament_minimizer = \"preconditioned_lbfgs\"\n");
  EXPECT_NE(wrong.find("mechanics.filament_minimizer"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("\"auto\" only"), std::string::npos) << wrong;
  const std::string unknown = errorOf(kMembrane + kFilaments + "[mechanics]\nfilament_minimizer = \"newton\"\n");
  EXPECT_NE(unknown.find("mechanics.filament_minimizer"), std::string::npos) << unknown;
}

}  // namespace
}  // namespace cortex
