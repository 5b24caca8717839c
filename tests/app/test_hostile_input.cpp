// Issue 11: input a hostile or careless user gives. Names that cannot name files or HDF5
// groups, control characters in --set, out-of-range seeds, paths that are folders or
// devices, models whose work or memory has no bound (output folders and resumes:
// test_hostile_output_folders.cpp): each is an error (exit 2) naming the key or
// path, in `check` as in `run`, before anything is written.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <tuple>

#include "app/cli_helpers.hpp"
#include "app/hostile_configs.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/mesh_file.hpp"
#include "mesh/planar_patch.hpp"

namespace cortex::cli_test {
namespace {

// Names become HDF5 groups, file names and XDMF text. NUL truncated them (two membranes
// overwrote each other), "." failed half-way through the first snapshot.
TEST(HostileInput, NamesThatCannotNameGroupsOrFilesAreRefused) {
  TempDir dir;
  for (const std::string& name : {std::string("ve\\u0000s"), std::string("."), std::string(".."), std::string("a/b"),
                                  std::string("a b"), std::string(""), std::string(65, 'x'), std::string("tab\\t")}) {
    expectRefusedInCheckAndRun(dir, replaced(kVesicle, "name = \"vesicle\"", "name = \"" + name + "\""),
                               "membrane.0.name", "membrane name \"" + name + "\"");
    expectRefusedInCheckAndRun(dir, replaced(kSpecies, "name = \"A\"", "name = \"" + name + "\""), "species.0.name",
                               "species name \"" + name + "\"");
  }
}

TEST(HostileInput, SetValuesWithControlCharactersAreRefused) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), kVesicle);
  for (const std::string& value : {std::string("simulation.end_time=0.01\nsimulation.seed=3"),
                                   std::string("membrane.0.name=\"a\rb\"")}) {
    const RunResult r = runCortex({"check", config.string(), "--set", value}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << describe(r);
    EXPECT_NE(r.err.find("control character"), std::string::npos) << describe(r);
  }
}

TEST(HostileInput, SeedsOutOfRangeAreRefusedNotClamped) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), kVesicle);
  for (const char* seed : {"99999999999999999999", "-1", "12x", "1e3"}) {
    const RunResult r = runConfig(config, dir / "out", {"--seed", seed}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << describe(r);
    EXPECT_NE(r.err.find("--seed"), std::string::npos) << describe(r);
  }
  const RunResult ok = runConfig(config, dir / "ok", {"--seed", "9223372036854775807"}, dir.path());
  EXPECT_EQ(ok.exit_code, 0) << describe(ok);
  EXPECT_EQ(readJson(dir / "ok" / "summary.json")["seed"].get<std::int64_t>(), 9223372036854775807LL);
}

// A folder, a device that never ends: refused by name before reading (it used to read
// /dev/zero until killed).
// /dev/zero as a config (or a sweep's base) was read until memory ran out; a folder said
// "nothing to simulate".
TEST(HostileInput, ConfigsThatAreNotRegularFilesAreRefused) {
  TempDir dir;
  for (const std::string& path : {std::string("/dev/zero"), dir.path().string()}) {
    const RunResult r = runCortex({"check", path}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << describe(r);
    EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << describe(r);
  }
  const fs::path sweep = writeConfig(dir.path(), "base = \"/dev/zero\"\nseeds = 2\n", "sweep.toml");
  const RunResult r = runCortex({"check", sweep.string()}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << describe(r);
}

TEST(HostileInput, MeshFilesThatAreNotRegularFilesAreRefused) {
  TempDir dir;
  fs::create_directories(dir / "folder.obj");
  for (const std::string& file : {(dir / "folder.obj").string(), std::string("/dev/zero")}) {
    const std::string text = "[simulation]\nend_time = 0.0\n[[membrane]]\nname = \"m\"\nshape = \"mesh\"\nfile = \"" +
                             file + "\"\n";
    expectRefusedInCheckAndRun(dir, text, file, "mesh file " + file);
  }
}

// Rates or diffusion constants that would fire ~1e300 events in a window ran until
// killed; they are refused by `check` and `run` naming the channel.
TEST(HostileInput, UnboundedChemistryIsRefusedNamingTheChannel) {
  TempDir dir;
  expectRefusedInCheckAndRun(dir, replaced(kSpecies, "diffusion = 1.0e6", "diffusion = 1.0e300"),
                             "diffusion of \"A\"", "diffusion 1e300");
  expectRefusedInCheckAndRun(dir, std::string(kSpecies) + "[[reaction]]\nequation = \"-> A\"\nrate = 1.0e12\n",
                             "max_events_per_window", "zeroth-order rate 1e12");
}

// Sizes whose meshes or grids would take gigabytes and minutes to build: `check` ran for
// minutes or never returned. Each is refused at once naming the key (a mesh_size in the
// wrong unit, a membrane a metre away or across, a grid of 2.7e7 compartments, a run of
// 1e300 s).
TEST(HostileInput, SizesThatCannotBeBuiltAreRefusedNamingTheKey) {
  TempDir dir;
  expectRefusedInCheckAndRun(dir, replaced(kVesicle, "mesh_size = 40.0", "mesh_size = 0.1"), "membrane.0.mesh_size",
                             "mesh_size 0.1 nm on a 200 nm sphere (5e7 vertices)");
  expectRefusedInCheckAndRun(dir, replaced(kVesicle, "radius = 200.0", "radius = 1.0e300"), "membrane.0.radius",
                             "radius 1e300");
  expectRefusedInCheckAndRun(dir, replaced(kVesicle, "radius = 200.0", "radius = 200.0\ncenter = [1.0e300, 0, 0]"),
                             "membrane.0.center", "center 1e300");
  expectRefusedInCheckAndRun(dir, replaced(kSpecies, "shape = [2, 2, 2]", "shape = [300, 300, 300]"),
                             "compartments.shape", "2.7e7 compartments");
  expectRefusedInCheckAndRun(dir, replaced(kSpecies, "end_time = 0.02", "end_time = 1.0e300"), "simulation.end_time",
                             "end_time 1e300 s");
}

// A mesh_size the marching-tetrahedra mesher cannot resolve (the docs allowed up to the
// radius) named the mesher's function; it names the key and the limit, for spheres and
// thin ellipsoids alike.
TEST(HostileInput, AMeshTooCoarseForItsShapeNamesMeshSize) {
  TempDir dir;
  expectRefusedInCheckAndRun(dir, replaced(kVesicle, "radius = 200.0\nmesh_size = 40.0", "radius = 40.0\nmesh_size = 40.0"),
                             "mesh_size = 40 nm is too coarse", "sphere of radius 40 at mesh 40");
  expectRefusedInCheckAndRun(dir,
                             replaced(replaced(kVesicle, "shape = \"sphere\"", "shape = \"ellipsoid\""),
                                      "radius = 200.0", "radii = [400.0, 400.0, 40.0]"),
                             "under about 0.7 x that radius", "ellipsoid 40 nm thin at mesh 40");
}

// A stiffness whose forces dwarf the force tolerance cannot be relaxed to it: bending
// 1e300 ran 30 s to exit 1, a filament's 1e300 failed with "largest force inf" naming no
// key. Refused (exit 2) against the scale it makes (io/resolvable_forces.hpp); a stiff
// but physical membrane (κ = 1e5 pN·nm, 2.4e4 k_BT) still runs.
TEST(HostileInput, StiffnessesNoRelaxationCanResolveAreRefused) {
  TempDir dir;
  expectRefusedInCheckAndRun(dir, replaced(kVesicle, "mesh_size = 40.0", "mesh_size = 40.0\nbending_modulus = 1e9"),
                             "membrane.0.bending_modulus", "bending 1e9 pN nm (2.5e7 pN at 40 nm)");
  expectRefusedInCheckAndRun(dir, replaced(kVesicle, "mesh_size = 40.0", "mesh_size = 40.0\ntension = -1e300"),
                             "membrane.0.tension", "tension -1e300");
  // A negative tension with no area term has no energy minimum: it passed check and the
  // run failed far from equilibrium without naming the key. A held area bounds it.
  const std::string pulling = replaced(kVesicle, "mesh_size = 40.0", "mesh_size = 40.0\ntension = -0.001");
  expectRefusedInCheckAndRun(dir, replaced(pulling, "tension", "area_model = \"none\"\ntension"), "membrane.0.tension",
                             "tension -0.001 pN/nm with no area term");
  expectRefusedInCheckAndRun(dir, replaced(pulling, "tension", "area_model = \"global\"\narea_modulus = [[0.0, 0.0], [1.0, 400.0]]\ntension"),
                             "membrane.0.tension", "tension -0.001 pN/nm against an area modulus ramped up from 0");
  const fs::path held = writeConfig(dir.path(), pulling, "held.toml");
  const RunResult held_run = runConfig(held, dir / "held", {}, dir.path());
  EXPECT_EQ(held_run.exit_code, 0) << describe(held_run);
  expectRefusedInCheckAndRun(dir, replaced(kVesicle, "[[membrane]]", "[mechanics]\nforce_tolerance = 1e-8\n[[membrane]]"),
                             "membrane.0.bending_modulus", "default bending against a tolerance of 1e-8 pN");
  const std::string filaments = std::string(kSpecies) + "[[filament_type]]\nname = \"actin\"\n";
  expectRefusedInCheckAndRun(dir, filaments + "bending_stiffness = 1e300\n", "filament_type.0.bending_stiffness",
                             "filament bending 1e300");
  expectRefusedInCheckAndRun(dir, filaments + "excluded_volume_distance = 1e300\n",
                             "filament_type.0.excluded_volume_distance", "excluded volume distance 1e300");
  // A motor's stiffness or a boundary's repulsion of 1e300 failed with "largest force inf".
  const std::string motor = filaments + "[[motor]]\nspecies = \"A\"\n";
  expectRefusedInCheckAndRun(dir, motor + "stiffness = 1e300\n", "motor.0.stiffness", "motor stiffness 1e300");
  expectRefusedInCheckAndRun(dir, filaments + "[boundary]\nrepulsion = 1e300\n", "boundary.repulsion",
                             "boundary repulsion 1e300");
  // Rounded to whole monomers, a step of 1e300 nm overflowed and walked like 2.7 nm.
  expectRefusedInCheckAndRun(dir, motor + "step_size = 1e300\n", "motor.0.step_size", "motor step 1e300 nm");
  // And a step under half a monomer (2.7 nm) rounded to none and was taken as one: 1 nm
  // walked 2.7 times as far as asked, 0.001 nm 2,700 times, exit 0.
  expectRefusedInCheckAndRun(dir, motor + "step_size = 1.0\n", "motor.0.step_size", "motor step 1 nm");
  // Cylinders of 0.044 nm (monomer_size 0.0011) overlapped their own filament's excluded
  // volume: 83 s to exit 1 with 1e6 pN, or 4 GB placing linker sites.
  expectRefusedInCheckAndRun(dir, filaments + "monomer_size = 0.0011\n", "filament_type.0.monomer_size",
                             "cylinders of 0.044 nm");
  // Binding at 1e9 /(µM·s) took the few site pairs at once and spent the window on void
  // draws (70 s for 0.1 s); over 1e6 is refused, a physical on-rate is accepted.
  expectRefusedInCheckAndRun(dir, motor + "on_rate = 1e9\n", "motor.0.on_rate", "motor on-rate 1e9");
  const fs::path fast = writeConfig(dir.path(), motor + "on_rate = 1e3\n", "fast.toml");
  const RunResult fast_check = runCortex({"check", fast.string()}, dir.path());
  EXPECT_EQ(fast_check.exit_code, 0) << describe(fast_check);

  const std::string coupled = std::string(kVesicle) + "[[filament_type]]\nname = \"actin\"\n[membrane_filament]\n";
  expectRefusedInCheckAndRun(dir, coupled + "stiffness = 1e12\n", "membrane_filament.stiffness",
                             "membrane-bead stiffness 1e12 pN nm³");
  // A cut-off past the vesicle's radius made every bead feel its far side; with a
  // stiffness of 1e12 that run never finished its first relaxation.
  expectRefusedInCheckAndRun(dir, coupled + "cutoff = 500.0\n", "membrane_filament.cutoff", "cutoff 500 nm, radius 200");
  // The push also acts on the membrane, which relaxes to its own force scale (about
  // 0.02 pN here) when no tolerance is given: 1e8 (6.3e5 pN, resolvable at 0.1 pN) is not
  // resolvable there and is refused; given force_tolerance = 0.1, the same is accepted.
  // (1e11 with a 250 nm cut-off on a 300 nm vesicle passed check and failed after 80 s.)
  expectRefusedInCheckAndRun(dir, coupled + "stiffness = 1e8\n", "membrane \"vesicle\"'s own force scale",
                             "membrane-bead stiffness 1e8 pN nm³ against the membrane's tolerance");
  const fs::path given = writeConfig(
      dir.path(), "[mechanics]\nforce_tolerance = 0.1\n" + coupled + "stiffness = 1e8\n", "given.toml");
  const RunResult accepted = runCortex({"check", given.string()}, dir.path());
  EXPECT_EQ(accepted.exit_code, 0) << describe(accepted);

  const fs::path stiff =
      writeConfig(dir.path(), replaced(kVesicle, "mesh_size = 40.0", "mesh_size = 40.0\nbending_modulus = 1e5"));
  const RunResult run = runConfig(stiff, dir / "stiff", {}, dir.path());
  EXPECT_EQ(run.exit_code, 0) << describe(run);
  // Actin (100 pN/nm over 108 nm cylinders) relaxed to 1e-4 pN converges: accepted.
  const fs::path tight = writeConfig(dir.path(), "[mechanics]\nforce_tolerance = 1e-4\n" + filaments, "tight.toml");
  const RunResult check = runCortex({"check", tight.string()}, dir.path());
  EXPECT_EQ(check.exit_code, 0) << describe(check);
}

// A bundle spacing of 1e-300 nm laid coincident filaments, which their excluded volume
// cannot push apart (no direction), and ran to exit 0. Refused below the filament radius;
// 4 nm (the radius is 3.5 nm) is accepted.
TEST(HostileInput, BundlesOfFilamentsInsideOneAnotherAreRefused) {
  TempDir dir;
  const std::string bundle =
      std::string(kSpecies) + "[[filament_type]]\nname = \"actin\"\n[[filaments]]\ncount = 7\nplacement = \"bundle\"\n";
  expectRefusedInCheckAndRun(dir, bundle + "spacing = 1e-300\n", "filaments.0.spacing", "coincident bundle");
  const fs::path close = writeConfig(dir.path(), bundle + "spacing = 4.0\n", "close.toml");
  EXPECT_EQ(runCortex({"check", close.string()}, dir.path()).exit_code, 0);
}

// 10,000 filaments of 2 µm in 1 µm³ (77% of it filled by their bodies) ran `check` past
// 2 minutes and 2 GB: the linker and motor pairs in reach grow as the density squared.
// Over half the volume filled is refused naming the count; 7% is accepted.
TEST(HostileInput, FilamentsThatCannotFitWhereTheyStartAreRefused) {
  TempDir dir;
  const std::string filaments =
      std::string(kSpecies) + "[[filament_type]]\nname = \"actin\"\n[[filaments]]\nlength = 150.0\n";
  expectRefusedInCheckAndRun(dir, filaments + "count = 1500\n", "filaments.0.count",
                             "1500 filaments of 150 nm in 200³ nm³ (108% filled)");
  const fs::path sparse = writeConfig(dir.path(), filaments + "count = 100\n", "sparse.toml");
  EXPECT_EQ(runCortex({"check", sparse.string()}, dir.path()).exit_code, 0);
}

// A loaded mesh is read in nm: one a metre away, or one written in µm (a 200 nm vesicle
// as radius 0.2), ran to exit 0 with nonsense. Both are refused naming the file.
TEST(HostileInput, LoadedMeshesOutOfScaleAreRefused) {
  TempDir dir;
  for (const auto& [name, center, radius] :
       {std::tuple<std::string, double, double>{"far.obj", 1e10, 200.0}, {"micrometres.obj", 0.0, 0.2}}) {
    writeObj(dir / name, icosphere(Vec3(center, 0, 0), radius, 3));
    const std::string text = "[simulation]\nend_time = 0.0\n[[membrane]]\nname = \"m\"\nshape = \"mesh\"\nfile = \"" +
                             (dir / name).string() + "\"\n";
    expectRefusedInCheckAndRun(dir, text, name, "mesh " + name);
  }
}

// Area and volume terms that hold nothing. An explicit volume_modulus = 0 dropped the
// reduced_volume target (a sphere at v = 0.9997 where 0.85 was asked, exit 0); a tension
// on a vesicle with neither area nor volume held shrank it for seconds before exit 1; an
// exact area on a flat patch (the patches' default then) failed as soon as anything drove
// it, with non-finite forces. Each is refused naming its key, and a patch's area is free
// by default: a patch with H0 bulges (exit 0).
TEST(HostileInput, AreaAndVolumeTermsThatHoldNothingAreRefused) {
  TempDir dir;
  const std::string deflated = replaced(kVesicle, "mesh_size = 40.0", "mesh_size = 40.0\nreduced_volume = 0.85");
  expectRefusedInCheckAndRun(dir, replaced(deflated, "reduced_volume", "volume_modulus = 0.0\nreduced_volume"),
                             "membrane.0.volume_modulus", "volume target with a modulus of 0");
  const auto vesicleWith = [](const std::string& keys) {
    return replaced(kVesicle, "mesh_size = 40.0", "mesh_size = 40.0\n" + keys);
  };
  expectRefusedInCheckAndRun(dir, vesicleWith("area_model = \"global\"\narea_modulus = 0.0"), "membrane.0.area_modulus",
                             "a global area penalty of 0");
  expectRefusedInCheckAndRun(dir, vesicleWith("area_model = \"none\"\ntension = 0.01"), "membrane.0.tension",
                             "a tension on a vesicle with nothing holding area or volume");
  const std::string patch = R"([simulation]
end_time = 0.0
[[membrane]]
name = "patch"
shape = "plane"
size = [400.0, 400.0]
mesh_size = 40.0
bending_modulus = 100.0
spontaneous_curvature = 0.003
)";
  expectRefusedInCheckAndRun(dir, patch + "area_model = \"exact\"\n", "membrane.0.area_model",
                             "an exact area on a flat patch");
  const fs::path free = writeConfig(dir.path(), patch, "patch.toml");
  const RunResult run = runConfig(free, dir / "patch", {}, dir.path());
  ASSERT_EQ(run.exit_code, 0) << describe(run);
  // Flat, the patch's bending energy is 2κH0²A = 288 pN·nm; bulged towards its H0, less.
  const double bending = readJson(dir / "patch" / "summary.json")["membranes"][0]["energy"]["bending"].get<double>();
  EXPECT_LT(bending, 0.9 * 2.0 * 100.0 * 0.003 * 0.003 * 400.0 * 400.0);
  // The same patch loaded from a file (closed or open is known only once read): its area
  // is free by default too, and a tension on it is no vesicle shrinking to a point.
  writeObj(dir / "patch.obj", planarPatch(Vec3::Zero(), 400.0, 400.0, 40.0));
  const std::string loaded = replaced(replaced(patch, "shape = \"plane\"", "shape = \"mesh\"\nfile = \"" +
                                                                            (dir / "patch.obj").string() + "\""),
                                      "size = [400.0, 400.0]\nmesh_size = 40.0\n", "tension = 0.001\n");
  const fs::path from_file = writeConfig(dir.path(), loaded, "loaded.toml");
  const RunResult loaded_run = runConfig(from_file, dir / "loaded", {}, dir.path());
  ASSERT_EQ(loaded_run.exit_code, 0) << describe(loaded_run);
  EXPECT_TRUE(readJson(dir / "loaded" / "summary.json")["membranes"][0]["tension"].is_null())
      << "the area is free: no multiplier";
}

// A membrane is one surface: a file with two separate spheres was one membrane with the
// pair's area and volume (reduced volume 0.707, exit 0). Refused naming the file.
TEST(HostileInput, ALoadedMeshOfTwoSeparateSurfacesIsRefused) {
  TempDir dir;
  TriangleSoup two = icosphere(Vec3(0, 0, 0), 200.0, 3);
  const TriangleSoup other = icosphere(Vec3(600.0, 0, 0), 200.0, 3);
  const Index shift = static_cast<Index>(two.positions.size());
  two.positions.insert(two.positions.end(), other.positions.begin(), other.positions.end());
  for (Tri t : other.triangles) two.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  writeObj(dir / "two.obj", two);
  const std::string text = "[simulation]\nend_time = 0.0\n[[membrane]]\nname = \"m\"\nshape = \"mesh\"\nfile = \"" +
                           (dir / "two.obj").string() + "\"\n";
  expectRefusedInCheckAndRun(dir, text, "2 separate pieces", "a mesh of two spheres");
  writeObj(dir / "one.obj", other);
  const fs::path one = writeConfig(dir.path(), replaced(text, "two.obj", "one.obj"), "one.toml");
  EXPECT_EQ(runCortex({"check", one.string()}, dir.path()).exit_code, 0);
}

// A network that explodes within a window passes the load check at its start (little to
// fire yet) and then ran for hours; it stops with exit 1 naming the limit, within seconds.
// The same when a crowding cap turns the growth into void events, which the limit did not
// count: that run went on for ever, deaf to SIGTERM (the stop is taken between windows).
TEST(HostileInput, ChemistryExplodingWithinAWindowStops) {
  TempDir dir;
  const std::string in_the_cytosol =
      std::string(kSpecies) + "[[reaction]]\nequation = \"A -> 2 A\"\nrate = 1.0e4\n";
  const std::string on_a_crowded_membrane = std::string(kVesicle) +
                                            "[[membrane.species]]\nname = \"M\"\ndiffusion = 1.0e5\n"
                                            "footprint = 100.0\ndensity = 100.0\n"
                                            "[[reaction]]\nequation = \"M -> 2 M\"\nrate = 1.0e6\n";
  for (const std::string& text : {in_the_cytosol, on_a_crowded_membrane}) {
    const fs::path config = writeConfig(dir.path(), text, "exploding.toml");
    const RunResult check = runCortex({"check", config.string()}, dir.path());
    EXPECT_EQ(check.exit_code, 0) << describe(check);
    const auto start = std::chrono::steady_clock::now();
    const RunResult run =
        runConfig(config, dir / "out", {"--overwrite", "--set", "chemistry.max_events_per_window=3e6"}, dir.path());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(run.exit_code, 1) << describe(run);
    EXPECT_NE(run.err.find("max_events_per_window"), std::string::npos) << describe(run);
    EXPECT_NE(run.err.find("growing without bound"), std::string::npos) << describe(run);
    EXPECT_LT(seconds, 30.0);  // ~10⁶ events: about a second; before, hours or never
  }
}

// A stoichiometry of 999,999 overflows a copy number within a window: exit 1 naming the
// reaction and the species (it said "copies of species 1 in subvolume 0"), with either engine.
TEST(HostileInput, CopyNumbersPastTheirLimitNameTheReaction) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(),
                                      std::string(kSpecies) + "[[species]]\nname = \"B\"\n[[reaction]]\n"
                                                              "equation = \"A -> A + 999999 B\"\nrate = 1.0e5\n",
                                      "overflow.toml");
  for (const std::string engine : {"nsm", "direct"}) {
    const RunResult run =
        runConfig(config, dir / "out", {"--overwrite", "--set", "chemistry.engine=\"" + engine + "\""}, dir.path());
    EXPECT_EQ(run.exit_code, 1) << engine << "\n" << describe(run);
    EXPECT_NE(run.err.find("reaction \"A -> A + 999999 B\" would take the copies of \"B\""), std::string::npos)
        << engine << "\n" << describe(run);
  }
}

// A run that fails before its first checkpoint does not claim to keep one.
// A filament type without a monomer species reacts with nothing; beside [[species]] its
// empty reaction range sat where the config's empty one did, and the engine took one
// for the other ("internal error: rate factors ... claimed already").
TEST(HostileInput, AMechanicsOnlyFilamentTypeBesideSpeciesRuns) {
  TempDir dir;
  const fs::path config =
      writeConfig(dir.path(), std::string(kSpecies) + "[[filament_type]]\nname = \"actin\"\n", "mechanics_only.toml");
  const RunResult check = runCortex({"check", config.string()}, dir.path());
  EXPECT_EQ(check.exit_code, 0) << describe(check);
  const RunResult run = runConfig(config, dir / "out", {}, dir.path());
  EXPECT_EQ(run.exit_code, 0) << describe(run);
}

TEST(HostileInput, FailureBeforeTheFirstCheckpointSaysNoneWasWritten) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), replaced(kVesicle, "[[membrane]]",
                                                           "[mechanics]\nminimizer = \"cg\"\nmax_iterations = 1\n"
                                                           "force_tolerance = 1e-4\n[[membrane]]"));
  const RunResult r = runConfig(config, dir / "out", {}, dir.path());
  ASSERT_EQ(r.exit_code, 1) << describe(r);
  EXPECT_NE(r.err.find("no checkpoint was written"), std::string::npos) << describe(r);
}

// 10,000 filaments with myosin and cross-linkers in a 4 µm box: the binding-pair search
// is linear in the sites (it was quadratic: 4 GB at 4,000 filaments, bad_alloc at 10,000
// even in `check`). `check` and a first window stay far below 2 GB (measured: 64 MB and
// 94 MB).
TEST(HostileInput, TenThousandFilamentsWithMyosinCheckAndStartInLittleMemory) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), R"([simulation]
end_time = 0.01
chemistry_window = 0.01
snapshot_interval = 0.01
[mechanics]
force_tolerance = 1.0
[compartments]
size = 500.0
shape = [8, 8, 8]
[[species]]
name = "G"
diffusion = 2.0e7
concentration = 10.0
[[species]]
name = "MII"
diffusion = 2.0e5
copies = 5000
[[species]]
name = "AA"
diffusion = 2.0e6
copies = 20000
[[filament_type]]
name = "actin"
monomer_species = "G"
[[filaments]]
type = "actin"
count = 10000
length = 500.0
[boundary]
shape = "box"
[[motor]]
name = "myosin"
species = "MII"
[[linker]]
name = "alpha-actinin"
species = "AA"
)");
  RunResult r = runCortex({"check", config.string()}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  r = runConfig(config, dir / "out", {"--threads", "1"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);  // the largest child so far, in KiB
  EXPECT_LT(usage.ru_maxrss, 2L * 1024 * 1024) << "KiB";
  RecordProperty("max_rss_kib", static_cast<int>(usage.ru_maxrss));
}

}  // namespace
}  // namespace cortex::cli_test
