// The command-line contract for bad input: `cortex check` / `cortex run` exit with code 2
// and a message naming the file and the offending key (or line); good input passes.
// Runs the real program (CORTEX_BINARY) on configs written per test.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "app/cli_helpers.hpp"

namespace cortex::cli_test {
namespace {

// A valid config whose [[membrane]] body is `membrane` (tiny: builds in milliseconds).
std::string configWith(const std::string& membrane, const std::string& before = "") {
  return before +
         "\n[simulation]\nseed = 1\nend_time = 0.0\n\n"
         "[mechanics]\nforce_tolerance = 0.5\n\n"
         "[[membrane]]\nname = \"vesicle\"\nshape = \"sphere\"\n" +
         membrane + "\n";
}

const std::string kSphere = "radius = 200.0\nmesh_size = 40.0\n";

class CliErrors : public ::testing::Test {
 protected:
  // `cortex check CONFIG [extra...]` on `text` written to dir/config.toml.
  RunResult check(const std::string& text, const std::vector<std::string>& extra = {}) {
    config_ = writeConfig(dir_.path(), text);
    std::vector<std::string> args{"check", config_.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return runCortex(args, dir_.path());
  }

  // Exit code 2, and stderr names the config file and every one of `needles`.
  void expectInputError(const RunResult& r, const std::vector<std::string>& needles,
                        bool names_config_file = true) const {
    EXPECT_EQ(r.exit_code, 2) << describe(r);
    if (names_config_file) {
      EXPECT_NE(r.err.find(config_.string()), std::string::npos) << "message does not name the file\n"
                                                                 << describe(r);
    }
    for (const std::string& n : needles)
      EXPECT_NE(r.err.find(n), std::string::npos) << "message does not mention '" << n << "'\n" << describe(r);
  }

  TempDir dir_;
  fs::path config_;
};

TEST_F(CliErrors, ValidConfigPasses) {
  const RunResult r = check(configWith(kSphere));
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_NE(r.out.find("ok"), std::string::npos) << describe(r);
}

// A sphere meshed so coarsely that its bending energy is percents off is accepted (a
// user's choice) but said so: mesh_size 0.72 R made a 14-vertex "sphere" 20% above 8πκ
// without a word. R/5 (mean edge ~0.2 R, 0.5%) passes quietly.
TEST_F(CliErrors, ACoarselyMeshedSphereIsWarnedOf) {
  const RunResult coarse = check(configWith("radius = 500.0\nmesh_size = 360.0\n"));
  EXPECT_EQ(coarse.exit_code, 0) << describe(coarse);
  EXPECT_NE(coarse.err.find("mesh_size = 360 nm gives 14 vertices"), std::string::npos) << describe(coarse);
  EXPECT_NE(coarse.err.find("off by percents"), std::string::npos) << describe(coarse);
  const RunResult fine = check(configWith("radius = 500.0\nmesh_size = 100.0\n"));
  EXPECT_EQ(fine.exit_code, 0) << describe(fine);
  EXPECT_EQ(fine.err.find("off by percents"), std::string::npos) << describe(fine);
}

TEST_F(CliErrors, UnknownKeyIsNamed) {
  expectInputError(check(configWith(kSphere + "bending_modulu = 3.0\n")),
                   {"membrane.0.bending_modulu", "unknown key"});
}

TEST_F(CliErrors, UnknownKeyInSimulationIsNamed) {
  const std::string text = "[simulation]\nend_tme = 1.0\n\n[[membrane]]\n" + kSphere;
  expectInputError(check(text), {"simulation.end_tme", "unknown key"});
}

TEST_F(CliErrors, UnknownTopLevelSectionIsNamed) {
  expectInputError(check(configWith(kSphere, "[simulaton]\nseed = 2\n")), {"simulaton", "unknown key"});
}

// A typo of a *required* key: `radiuss` instead of `radius`.
// KNOWN WEAKNESS (src/io/config.cpp readShape -> ConfigReader::requiredNumber): the
// missing `radius` is reported before finish() gets to the unknown key, so the message is
// "membrane.0.radius: is required but missing" and never names the typo `radiuss`. It
// still exits 2 and points at `radius`, so this is a usability issue, not a silent pass:
// skipped (not failed) until the reader reports unknown keys of a table first or adds
// "(did you mean ...)".
TEST_F(CliErrors, TypoOfRequiredKeyIsRejected) {
  const RunResult r = check(configWith("radiuss = 200.0\nmesh_size = 40.0\n"));
  expectInputError(r, {"membrane.0.radius", "radiuss"});
}

TEST_F(CliErrors, WrongTypeIsNamed) {
  expectInputError(check(configWith("radius = \"big\"\nmesh_size = 40.0\n")), {"membrane.0.radius", "number"});
  expectInputError(check(configWith(kSphere + "remesh = 3\n")), {"membrane.0.remesh"});
  expectInputError(check(configWith(kSphere + "center = [0.0, 0.0]\n")), {"membrane.0.center"});
}

TEST_F(CliErrors, OutOfRangeIsNamed) {
  expectInputError(check(configWith("radius = -5\nmesh_size = 40.0\n")), {"membrane.0.radius", "-5"});
  expectInputError(check(configWith("radius = 0.0\nmesh_size = 40.0\n")), {"membrane.0.radius"});
  expectInputError(check(configWith("radius = 200.0\nmesh_size = 400.0\n")), {"membrane.0.mesh_size"});
  expectInputError(check(configWith(kSphere + "bending_modulus = -1.0\n")), {"membrane.0.bending_modulus"});
  expectInputError(check(configWith(kSphere + "reduced_volume = 1.5\n")), {"membrane.0.reduced_volume"});
  // The same as a volume: more than the sphere of the held area (R = 200 nm: 3.35e7 nm^3)
  // encloses, also when a schedule gets there later. It was held as the sphere, exit 0.
  expectInputError(check(configWith(kSphere + "target_volume = 4.0e7\n")), {"membrane \"", "target_volume", "> 1"});
  expectInputError(check(configWith(kSphere + "target_volume = [[0.0, 3.0e7], [1.0, 3.5e7]]\n")),
                   {"target_volume", "t = 1 s"});
  expectInputError(check("[[membrane]]\nshape = \"cube\"\n" + kSphere), {"membrane.0.shape", "cube"});
}

TEST_F(CliErrors, ForceToleranceZeroIsRejected) {
  const std::string text = "[mechanics]\nforce_tolerance = 0\n\n[[membrane]]\n" + kSphere;
  expectInputError(check(text), {"mechanics.force_tolerance"});
}

TEST_F(CliErrors, BadTimesAreRejected) {
  const std::string membrane = "\n[[membrane]]\n" + kSphere;
  expectInputError(check("[simulation]\nend_time = -1.0\n" + membrane), {"simulation.end_time"});
  expectInputError(check("[simulation]\nchemistry_window = 0.0\n" + membrane), {"simulation.chemistry_window"});
  expectInputError(check("[simulation]\nsnapshot_interval = -0.1\n" + membrane), {"simulation.snapshot_interval"});
  expectInputError(check("[simulation]\nseed = 1.5\n" + membrane), {"simulation.seed"});
}

struct BadValue {
  std::string simulation;  // lines for [simulation]
  std::string membrane;    // extra lines for [[membrane]]
  std::string key;         // expected in the message
};

class NonFiniteValues : public CliErrors, public ::testing::WithParamInterface<BadValue> {};

TEST_P(NonFiniteValues, AreRejectedNamingTheKey) {
  const BadValue& b = GetParam();
  const std::string text = "[simulation]\n" + b.simulation + "\n\n[[membrane]]\n" + b.membrane + "\n";
  const RunResult r = check(text);
  expectInputError(r, {b.key});
  EXPECT_TRUE(r.err.find("nan") != std::string::npos || r.err.find("inf") != std::string::npos ||
              r.err.find("finite") != std::string::npos)
      << describe(r);
}

INSTANTIATE_TEST_SUITE_P(
    CliErrors, NonFiniteValues,
    ::testing::Values(BadValue{"", "radius = nan\nmesh_size = 40.0", "membrane.0.radius"},
                      BadValue{"", "radius = inf\nmesh_size = 40.0", "membrane.0.radius"},
                      BadValue{"", "radius = -inf\nmesh_size = 40.0", "membrane.0.radius"},
                      BadValue{"", "radius = 200.0\nmesh_size = nan", "membrane.0.mesh_size"},
                      BadValue{"end_time = inf", kSphere, "simulation.end_time"},
                      BadValue{"chemistry_window = nan", kSphere, "simulation.chemistry_window"},
                      BadValue{"", kSphere + "center = [0.0, nan, 0.0]", "membrane.0.center"},
                      BadValue{"", kSphere + "bending_modulus = [[0.0, 1.0], [0.1, nan]]",
                               "membrane.0.bending_modulus"},
                      BadValue{"", kSphere + "tension = [[0.0, 0.0], [inf, 1.0]]", "membrane.0.tension"}));

TEST_F(CliErrors, ScheduleTimesMustIncrease) {
  expectInputError(check(configWith(kSphere + "reduced_volume = [[0.0, 1.0], [0.0, 0.9]]\n")),
                   {"membrane.0.reduced_volume", "increase"});
  expectInputError(check(configWith(kSphere + "reduced_volume = [[0.5, 1.0], [0.2, 0.9]]\n")),
                   {"membrane.0.reduced_volume", "increase"});
  expectInputError(check(configWith(kSphere + "tension = [[0.0, 1.0], 2.0]\n")), {"membrane.0.tension"});
  // A well-formed schedule passes.
  const RunResult ok = check(configWith(kSphere + "reduced_volume = [[0.0, 1.0], [0.2, 0.9]]\n"));
  EXPECT_EQ(ok.exit_code, 0) << describe(ok);
}

TEST_F(CliErrors, InvalidTomlNamesTheLine) {
  // Line 5 holds the syntax error.
  const std::string text = "[simulation]\nseed = 1\n\n[[membrane]]\nradius = = 200.0\nmesh_size = 40.0\n";
  const RunResult r = check(text);
  expectInputError(r, {});
  EXPECT_NE(r.err.find(config_.string() + ":5"), std::string::npos) << "message does not name line 5\n"
                                                                    << describe(r);
  // An unterminated string on line 2.
  const RunResult r2 = check("[simulation]\nseed = \"1\n");
  expectInputError(r2, {});
  EXPECT_NE(r2.err.find(config_.string() + ":2"), std::string::npos) << describe(r2);
}

TEST_F(CliErrors, MissingConfigFile) {
  const fs::path missing = dir_ / "no_such_config.toml";
  RunResult r = runCortex({"check", missing.string()}, dir_.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find(missing.string()), std::string::npos) << describe(r);
  r = runCortex({"run", missing.string(), "-o", (dir_ / "out").string(), "-q"}, dir_.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find(missing.string()), std::string::npos) << describe(r);
}

TEST_F(CliErrors, SetWithBadPath) {
  RunResult r = check(configWith(kSphere), {"--set", "membrane.5.radius=300"});
  expectInputError(r, {"membrane.5.radius"}, /*names_config_file=*/false);
  // The same through `run` (nothing is simulated).
  r = runCortex({"run", config_.string(), "-o", (dir_ / "out").string(), "-q", "--set", "membrane.5.radius=300"},
                dir_.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("membrane.5.radius"), std::string::npos) << describe(r);
  EXPECT_FALSE(fs::exists(dir_ / "out" / "summary.json"));
  // Not key=value at all; a key below a scalar; a misspelt key (caught by validation).
  expectInputError(check(configWith(kSphere), {"--set", "membrane.0.radius"}), {"membrane.0.radius"}, false);
  expectInputError(check(configWith(kSphere), {"--set", "simulation.end_time.x=1"}), {"simulation.end_time"},
                   false);
  expectInputError(check(configWith(kSphere), {"--set", "membrane.0.radiuss=300"}), {"membrane.0.radiuss"},
                   false);
  expectInputError(check(configWith(kSphere), {"--set", "membrane.0.radius=-3"}), {"membrane.0.radius"}, false);
  // An entry of an array of tables given a value: it said "cannot set a key inside a non-table".
  expectInputError(check(configWith(kSphere), {"--set", "membrane.0=1"}),
                   {"--set membrane.0=1", "cannot be replaced by a value"}, false);
  // A numeral past a double's range is not a bare word: it was taken as a string and
  // reported as "must be a number, got string". A bare word still is a string.
  const RunResult huge = check(configWith(kSphere), {"--set", "simulation.end_time=1e400"});
  expectInputError(huge, {"--set simulation.end_time=1e400", "does not read as a number"}, false);
  EXPECT_EQ(huge.err.find("got string"), std::string::npos) << describe(huge);
  expectInputError(check(configWith(kSphere), {"--set", "simulation.end_time=soon"}),
                   {"simulation.end_time", "got string"});
}

TEST_F(CliErrors, SetChangesValues) {
  RunResult r = check(configWith(kSphere), {"--set", "simulation.end_time=0.5"});
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_NE(r.out.find("end_time 0.5 s"), std::string::npos) << describe(r);

  // A bigger radius gives a mesh with more vertices.
  const std::regex vertices_re("([0-9]+) vertices");
  std::smatch m;
  r = check(configWith(kSphere));
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  ASSERT_TRUE(std::regex_search(r.out, m, vertices_re)) << describe(r);
  const long small = std::stol(m[1]);
  r = check(configWith(kSphere), {"--set", "membrane.0.radius=300"});
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  ASSERT_TRUE(std::regex_search(r.out, m, vertices_re)) << describe(r);
  EXPECT_GT(std::stol(m[1]), small) << describe(r);

  // Through a run: a string value, a number and --seed all reach the summary.
  const fs::path out = dir_ / "out";
  r = runCortex({"run", config_.string(), "-o", out.string(), "-q", "--seed", "7", "--set",
                 "membrane.0.name=cell", "--set", "membrane.0.mesher=\"icosphere\""},
                dir_.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const nlohmann::json s = readJson(out / "summary.json");
  EXPECT_EQ(s["seed"], 7);
  EXPECT_EQ(s["membranes"][0]["name"], "cell");
  // A closed genus-0 triangulation: F = 2V - 4.
  EXPECT_EQ(s["membranes"][0]["triangles"].get<long>(), 2 * s["membranes"][0]["vertices"].get<long>() - 4);
}

TEST_F(CliErrors, VolumeKeysOnPlaneAreRejected) {
  for (const char* key : {"volume_modulus = 0.8", "reduced_volume = 0.9", "target_volume = 1.0e6"}) {
    const std::string text = "[[membrane]]\nname = \"patch\"\nshape = \"plane\"\nsize = [400.0, 400.0]\n"
                             "mesh_size = 40.0\n" + std::string(key) + "\n";
    const std::string name = std::string(key).substr(0, std::string(key).find(' '));
    expectInputError(check(text), {"membrane.0." + name});
  }
  const RunResult ok =
      check("[[membrane]]\nshape = \"plane\"\nsize = [400.0, 400.0]\nmesh_size = 40.0\ntension = 0.01\n");
  EXPECT_EQ(ok.exit_code, 0) << describe(ok);
}

TEST_F(CliErrors, MeshFileMissing) {
  const RunResult r = check("[[membrane]]\nname = \"cell\"\nshape = \"mesh\"\nfile = \"missing_cell.obj\"\n");
  // Relative paths resolve against the config's folder; the message names the mesh file.
  expectInputError(r, {"missing_cell.obj"}, /*names_config_file=*/false);
  const RunResult none = check("[[membrane]]\nshape = \"mesh\"\n");
  expectInputError(none, {"membrane.0.file"});
}

TEST_F(CliErrors, NonManifoldObjIsRejected) {
  // Three triangles sharing the edge 1-2: not a 2-manifold.
  writeFile(dir_ / "fin.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
            "f 1 2 3\nf 2 1 4\nf 1 2 5\n");
  const RunResult r = check("[[membrane]]\nname = \"cell\"\nshape = \"mesh\"\nfile = \"fin.obj\"\n");
  expectInputError(r, {"fin.obj"}, /*names_config_file=*/false);
  // The same triangles in a run: bad input too, no outputs claimed.
  const RunResult run = runCortex({"run", config_.string(), "-o", (dir_ / "out").string(), "-q"}, dir_.path());
  EXPECT_EQ(run.exit_code, 2) << describe(run);
  EXPECT_NE(run.err.find("fin.obj"), std::string::npos) << describe(run);
}

// Chemistry sections that would be ignored are errors.
TEST_F(CliErrors, ChemistryKeysThatCannotWorkAreRejected) {
  expectInputError(check(configWith(kSphere, "[compartments]\nsize = 500.0\nshape = [2, 2, 2]\n")),
                   {"compartments", "[[species]]"});
  expectInputError(check(configWith(kSphere, "[[reaction]]\nequation = \"A -> B\"\nrate = 1.0\n")),
                   {"reaction", "[[species]]"});
  const std::string species = "[[species]]\nname = \"A\"\ndiffusion = 1.0\ncopies = 10\n";
  EXPECT_EQ(check(configWith(kSphere, species)).exit_code, 0) << "3D species are supported";
  expectInputError(check(configWith(kSphere, species + "inside = \"m\"\n")), {"species.0.inside"});
  expectInputError(check(configWith(kSphere, species + "[[reaction]]\nequation = \"A ->\"\nrate = 1.0\nregion = 1\n")),
                   {"reaction.0.region"});
  expectInputError(check(configWith(kSphere, species + "[[reaction]]\nequation = \"3 A -> B\"\nrate = 1.0\n")),
                   {"reaction.0.equation"});
  EXPECT_EQ(check(configWith(kSphere + "\n[[membrane.species]]\nname = \"M\"\ncopies = 10\n")).exit_code, 0)
      << "membrane species are supported";
  expectInputError(check(configWith(kSphere + "\n[[membrane.species]]\ncopies = 10\n")), {"membrane.0.species.0.name"});
  // A membrane species named like a 3D one, or like one of another membrane's, is told at
  // its own name key, not at its membrane's table.
  const std::string surface_m = "[[membrane.species]]\nname = \"M\"\ndiffusion = 1e5\n";
  const RunResult clash3d = check(configWith(kSphere + surface_m, "[[species]]\nname = \"M\"\ndiffusion = 1.0\ncopies = 1\n"));
  expectInputError(clash3d, {"membrane.0.species.0.name", "unique"});
  const std::string second =
      "[[membrane]]\nname = \"outer\"\nshape = \"sphere\"\nradius = 400.0\nmesh_size = 80.0\n" + surface_m;
  const RunResult clash2d = check(configWith(kSphere + surface_m + second, species));
  expectInputError(clash2d, {"membrane.1.species.0.name", "unique"});
}

// Filament tables through the CLI: a valid network passes `check` (placement included),
// and a misspelt key, a missing species or a filament that cannot fit stop with exit 2.
TEST_F(CliErrors, FilamentKeysAreCheckedEndToEnd) {
  const std::string base =
      "[compartments]\nsize = 500.0\nshape = [2, 2, 1]\n[[species]]\nname = \"G\"\ndiffusion = 2.0e7\ncopies = 100\n"
      "[[filament_type]]\nmonomer_species = \"G\"\n[[filaments]]\ncount = 5\n";
  const RunResult ok = check(base);
  EXPECT_EQ(ok.exit_code, 0) << describe(ok);
  EXPECT_NE(ok.out.find("5 filaments"), std::string::npos) << describe(ok);
  expectInputError(check(base + "lenght = 100.0\n"), {"filaments.0.lenght"});
  expectInputError(check(base + "[[linker]]\nspecies = \"AA\"\n"), {"linker.0.species", "AA"});
  expectInputError(check(base + "length = 5000.0\n"), {"filaments.0.length"});
  // A bundle wider than the box is refused when the system is built.
  expectInputError(check(base + "placement = \"bundle\"\nspacing = 400.0\n", {"--set", "filaments.0.count=7"}),
                   {"filaments.0", "does not fit"});
}

TEST_F(CliErrors, RunNeedsConfigOrResume) {
  RunResult r = runCortex({"run"}, dir_.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_FALSE(r.err.empty()) << describe(r);
  r = runCortex({"run", "-o", (dir_ / "out").string()}, dir_.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  // Both at once is ambiguous.
  config_ = writeConfig(dir_.path(), configWith(kSphere));
  r = runCortex({"run", config_.string(), "--resume", dir_.path().string()}, dir_.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  // --resume of a folder without a checkpoint names the checkpoint file.
  const fs::path empty = dir_ / "empty";
  fs::create_directories(empty);
  r = runCortex({"run", "--resume", empty.string()}, dir_.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("checkpoint.h5"), std::string::npos) << describe(r);
  // Unknown options and subcommands are bad input too.
  r = runCortex({"run", config_.string(), "--no-such-option"}, dir_.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  r = runCortex({"frobnicate"}, dir_.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
}

TEST_F(CliErrors, VersionExitsZero) {
  const RunResult r = runCortex({"--version"}, dir_.path());
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_NE(r.out.find(CORTEX_VERSION), std::string::npos) << describe(r);
  EXPECT_NE(r.out.find("cortex"), std::string::npos) << describe(r);
}

TEST_F(CliErrors, EveryExampleChecks) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(sourceDir() / "examples")) {
    if (entry.path().extension() != ".toml") continue;
    ++count;
    const RunResult r = runCortex({"check", entry.path().string()}, dir_.path());
    EXPECT_EQ(r.exit_code, 0) << entry.path() << '\n' << describe(r);
  }
  EXPECT_GT(count, 0) << "no examples/*.toml found";
}

}  // namespace
}  // namespace cortex::cli_test
