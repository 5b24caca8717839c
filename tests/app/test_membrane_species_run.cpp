// Membrane species through the whole program (issue 14): snapshots hold copies per
// vertex (and the XDMF shows them as point data), a resumed run is bit-identical to an
// uninterrupted one while the vesicle deflates and is remeshed, and config errors name
// the file, the key and the problem with exit code 2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numeric>
#include <tuple>

#include "app/cli_helpers.hpp"
#include "core/constants.hpp"
#include "core/types.hpp"
#include "io/hdf5_file.hpp"

namespace cortex::cli_test {
namespace {

std::string exampleText() { return readFile(sourceDir() / "examples" / "membrane_proteins.toml"); }

std::string proteinsConfig(double end_time) {
  std::string text = exampleText();
  const std::string key = "end_time = 0.05";
  text.replace(text.find(key), key.size(), fmt::format("end_time = {}", end_time));
  return text;
}

std::int64_t sum(const std::vector<std::int32_t>& v) { return std::accumulate(v.begin(), v.end(), std::int64_t{0}); }

TEST(MembraneSpeciesRun, SnapshotsHoldCopiesPerVertexAndResumeBitIdentically) {
  TempDir dir;
  runWholeAndResumed(dir, proteinsConfig, 0.02, 0.04);
  if (::testing::Test::HasFatalFailure()) return;
  EXPECT_EQ(comparableSummary(dir / "A"), comparableSummary(dir / "B"));
  const h5::File a = h5::File::openReadOnly(dir / "A" / "trajectory.h5");
  const h5::File b = h5::File::openReadOnly(dir / "B" / "trajectory.h5");
  ASSERT_EQ(a.children("/snapshots"), b.children("/snapshots"));
  std::set<std::size_t> vertex_counts;
  for (const std::string& s : a.children("/snapshots")) {
    const std::string g = "/snapshots/" + s + "/membranes/vesicle/";
    EXPECT_EQ(a.readDoubles(g + "vertices"), b.readDoubles(g + "vertices")) << s;
    for (const char* species : {"P", "M"}) EXPECT_EQ(a.readInt32(g + "species/" + species), b.readInt32(g + "species/" + species)) << s;
    const auto p = a.readInt32(g + "species/P");
    EXPECT_EQ(p.size(), a.readDoubles(g + "vertices").size() / 3) << s;
    EXPECT_EQ(sum(p), 5000) << s;
    EXPECT_EQ(sum(a.readInt32(g + "species/M")) + sum(a.readInt32("/snapshots/" + s + "/compartments/species/G")), 20000)
        << s;
    EXPECT_FALSE(a.exists("/snapshots/" + s + "/compartments/species/P")) << "a membrane species in the grid";
    vertex_counts.insert(p.size());
  }
  EXPECT_GT(vertex_counts.size(), 1u) << "the vesicle was never remeshed";
  const std::string xdmf = readFile(dir / "B" / "trajectory.xdmf");
  EXPECT_NE(xdmf.find(R"(<Attribute Name="P" AttributeType="Scalar" Center="Node">)"), std::string::npos);
  EXPECT_EQ(readJson(dir / "A" / "summary.json")["chemistry"]["species"]["P"].get<int>(), 5000);
  // And per membrane (it was always {}): P's copies are all on the vesicle.
  EXPECT_EQ(readJson(dir / "A" / "summary.json")["membranes"][0]["species"]["P"].get<int>(), 5000);
}

void replaceOnce(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

TEST(MembraneSpeciesRun, BadMembraneSpeciesNameTheKey) {
  std::string both = exampleText();
  replaceOnce(both, "copies = 5000", "copies = 5000\ndensity = 10.0");
  expectCheckFails(both, "membrane.0.species.0.density", "not both");

  std::string negative = exampleText();
  replaceOnce(negative, "diffusion = 1.0e6", "diffusion = -1.0");
  expectCheckFails(negative, "membrane.0.species.0.diffusion", "");

  std::string twice = exampleText();
  replaceOnce(twice, "name = \"M\"", "name = \"P\"");
  expectCheckFails(twice, "membrane.0.species.1.name", "twice");

  std::string clash = exampleText();
  replaceOnce(clash, "name = \"G\"", "name = \"M\"");
  expectCheckFails(clash, "membrane", "unique");

  std::string region = exampleText();
  replaceOnce(region, "rate = 100.0", "rate = 100.0\nregion = { min = [0.0, 0.0, 0.0], max = [900.0, 900.0, 900.0] }");
  expectCheckFails(region, "reaction.0.region", "membrane species");

  std::string nan = exampleText();
  replaceOnce(nan, "diffusion = 1.0e6", "diffusion = nan");
  expectCheckFails(nan, "membrane.0.species.0.diffusion", "finite");

  std::string soft = exampleText();
  replaceOnce(soft, "bending_modulus = 100.0", "bending_modulus = 0.0");
  replaceOnce(soft, "name = \"M\"", "name = \"M\"\ncurvature = { area = 10.0, bending_modulus = 50.0 }");
  expectCheckFails(soft, "membrane.0.bending_modulus", "senses curvature");

  // Copies of a species with a pair attraction or curvature sensing desorbing two at a time.
  for (const char* energy : {"interaction = { height = 0.1, range = 18.0 }", "curvature = { area = 10.0, bending_modulus = 50.0 }"}) {
    std::string dimer = exampleText();
    replaceOnce(dimer, "density = 0.0 ", std::string(energy) + "\ndensity = 0.0 ");
    replaceOnce(dimer, "equation = \"M -> G\"", "equation = \"2 M -> G\"");
    expectCheckFails(dimer, "reaction.1.equation", "one copy at a time");
  }
  // Cross interactions: with an unknown species or itself, declared on both sides, or
  // without a partner.
  auto cross = [](const std::string& partner) {
    return "cross_interaction = [{ " + partner + "height = 0.1, range = 18.0 }]\n";
  };
  for (const char* partner : {"X", "P"}) {
    std::string unknown = exampleText();
    replaceOnce(unknown, "name = \"P\"\n", "name = \"P\"\n" + cross("species = \"" + std::string(partner) + "\", "));
    expectCheckFails(unknown, "membrane.0.species.0.cross_interaction.0.species", "not another species");
  }
  std::string both_sides = exampleText();
  replaceOnce(both_sides, "name = \"P\"\n", "name = \"P\"\n" + cross("species = \"M\", "));
  replaceOnce(both_sides, "name = \"M\"\n", "name = \"M\"\n" + cross("species = \"P\", "));
  expectCheckFails(both_sides, "membrane.0.species.0.cross_interaction.0.species", "on one of the two");
  std::string no_partner = exampleText();
  replaceOnce(no_partner, "name = \"P\"\n", "name = \"P\"\n" + cross(""));
  expectCheckFails(no_partner, "membrane.0.species.0.cross_interaction.0.species", "required");
  // Proteins with a spontaneous curvature need the signed estimator (the default then).
  std::string unsigned_h = exampleText();
  replaceOnce(unsigned_h, "bending_modulus = 100.0", "bending_modulus = 100.0\ncurvature = \"unsigned\"");
  replaceOnce(unsigned_h, "name = \"M\"",
              "name = \"M\"\ncurvature = { area = 10.0, bending_modulus = 50.0, spontaneous_curvature = 0.01 }");
  expectCheckFails(unsigned_h, "membrane.0.curvature", "must be \"signed\"");
  std::string no_range = exampleText();
  replaceOnce(no_range, "name = \"P\"", "name = \"P\"\ninteraction = { height = 0.1, range = 0.0 }");
  expectCheckFails(no_range, "membrane.0.species.0.interaction.range", "");
  // A repulsion's mean field attracts at the mesh scale (it piled copies 4.6-fold over
  // Poisson onto a fifth of the vertices of examples/membrane_llps.toml): refused.
  std::string repulsive = exampleText();
  replaceOnce(repulsive, "name = \"P\"", "name = \"P\"\ninteraction = { height = -0.1, range = 18.0 }");
  expectCheckFails(repulsive, "membrane.0.species.0.interaction.height", "repulsive");

  std::string unknown = exampleText();
  replaceOnce(unknown, "copies = 5000", "copies = 5000\ncopise = 3");
  expectCheckFails(unknown, "copise", "");

  // Found when the mesh is built, still exit 2 naming the file: a start region that holds
  // no vertex, a density that would make more copies than 32-bit counts hold.
  std::string empty = exampleText();
  replaceOnce(empty, "min = [0.0, 0.0, 1400.0]", "min = [0.0, 0.0, 1700.0]");
  std::string dense = exampleText();
  replaceOnce(dense, "copies = 5000", "density = 1.0e12");
  // Named as keys are (an audit found them naming only the membrane and species).
  for (const auto& [text, words] : {std::pair{empty, "membrane.0.species.0.region (species \"P\""},
                                    std::pair{dense, "membrane.0.species.0.density (species \"P\""}}) {
    TempDir dir;
    const RunResult r = runConfig(writeConfig(dir.path(), text), dir / "out", {}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << describe(r);
    EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("config.toml"), std::string::npos) << r.err;
  }
}

// A 400 nm patch with one membrane species P (and a 3D species C): what a bad-input sweep
// found slipping through as "internal error" (exit 1), a run that check had passed, or a
// garbled message. `species` and `reactions` are appended to P's table and to the file.
std::string patchWith(const std::string& species, const std::string& reactions = "") {
  return R"([simulation]
end_time = 0.02
chemistry_window = 0.01
[[membrane]]
name = "patch"
shape = "plane"
center = [200.0, 200.0, 0.0]
size = [400.0, 400.0]
mesh_size = 25.0
boundary = "fixed"
bending_modulus = 100.0
area_model = "none"
[[membrane.species]]
name = "P"
diffusion = 1.0e6
copies = 300
)" + species + R"(
[compartments]
size = 200.0
shape = [2, 2, 1]
[[species]]
name = "C"
diffusion = 1.0e7
copies = 1000
)" + reactions;
}

TEST(MembraneSpeciesRun, ImpossibleParametersAreInputErrorsInCheckAsInRun) {
  // Energies that overflow the rates, found when the species are set up: exit 2 naming
  // the species and the block (they were exit 1, "internal error").
  expectCheckFails(patchWith("[membrane.species.potential]\nwidth = 1e-200\nheight = 2.0\ncenter = 200.0\n"),
                   "species \"P\": its potential", "not finite");
  expectCheckFails(patchWith("[membrane.species.interaction]\nheight = 0.1\nrange = 1e300\n"),
                   "species \"P\": its interaction", "not finite");
  // A potential beside an interaction rides in its field: both blocks are named (the
  // potential's fault was blamed on the interaction).
  expectCheckFails(patchWith("[membrane.species.interaction]\nheight = 0.1\nrange = 30.0\n"
                             "[membrane.species.potential]\nwidth = 1e-200\nheight = 2.0\ncenter = 200.0\n"),
                   "species \"P\": its interaction or potential", "not finite");
  expectCheckFails(patchWith("[membrane.species.potential]\ntype = \"ramp\"\nslope = 10.0\ncenter = 200.0\n",
                             "[[reaction]]\nequation = \"P -> C\"\nrate = 1.0\n"),
                   "\"P\" (membrane.0.species.0.potential)", "unbinding at r e^(beta V) overflows");
  // A strong attraction on a footprint: the mean field's vertex-scale term (proteins.md)
  // gives a copy in a crowded cell a leaving energy of up to ~300 k_BT, and its unbinding
  // multiplied past the events limit (exit 2 from check, naming the energies). With the
  // energy above 13.8 k_BT weighing binding instead (engine_base.hpp) it runs.
  {
    TempDir dir;
    const RunResult r = runCortex(
        {"check", writeConfig(dir.path(), patchWith("footprint = 20.0\n[membrane.species.interaction]\nheight = 5.0\n"
                                                    "range = 30.0\n",
                                                    "[[reaction]]\nequation = \"P -> C\"\nrate = 1.0\n"))
                      .string()},
        dir.path());
    EXPECT_EQ(r.exit_code, 0) << describe(r);
  }
  // A footprint past every vertex's cell: no copy could ever sit there (with no initial
  // copies, binding onto the membrane was accepted and fired 0 times).
  expectCheckFails(patchWith("footprint = 1.0e6\n"), "species.0.footprint", "exceeds the room of every vertex");
  // A pair interaction's range far past the mesh speeds the hops up by e^{βΔV}: the
  // message names the energy, not only the diffusion constant (it blamed diffusion alone).
  expectCheckFails(patchWith("[membrane.species.interaction]\nheight = 0.2\nrange = 1000.0\n"),
                   "the largest channel is diffusion of \"P\"", "interaction or curvature energy that drives its hops");
  // Every point of a bending-modulus schedule must be > 0 for curvature sensing.
  std::string schedule = patchWith("[membrane.species.curvature]\narea = 20.0\nbending_modulus = 100.0\n");
  replaceOnce(schedule, "bending_modulus = 100.0\narea_model", "bending_modulus = [[0.0, 100.0], [0.01, 0.0]]\narea_model");
  expectCheckFails(schedule, "membrane.0.bending_modulus", "(at t = 0.01 s)");
  // Two interacting copies leaving together, as "2 P -> C" (refused before) does.
  expectCheckFails(patchWith("[membrane.species.curvature]\narea = 20.0\nbending_modulus = 100.0\n"
                             "[[membrane.species]]\nname = \"Q\"\ndiffusion = 1.0e6\ncopies = 100\n",
                             "[[reaction]]\nequation = \"P + Q -> C\"\nrate = 1.0\n"),
                   "reaction.0.equation", "one copy at a time");
  expectCheckFails(patchWith("[membrane.species.interaction]\nheight = 10.01\nrange = 30.0\n"),
                   "membrane.0.species.0.interaction.height", "[0, 10]");
  // More curvature proteins than the membrane can hold (the 400 nm patch is 1.6e5 nm^2),
  // and a ramp centred so far out that its differences drown in rounding.
  std::string covering = patchWith("[membrane.species.curvature]\narea = 20.0\nbending_modulus = 100.0\n");
  replaceOnce(covering, "copies = 300", "copies = 20000");
  expectCheckFails(covering, "species \"P\"", "would cover 2.5 times");
  expectCheckFails(patchWith("[membrane.species.potential]\ntype = \"ramp\"\nslope = 0.01\ncenter = -1e300\n"),
                   "membrane.0.species.0.potential.center", "");
  // A footprint so small that a vertex's room overflowed 64-bit integers into a negative
  // count of places: accepted, as any positive footprint that fits.
  TempDir dir;
  const RunResult tiny =
      runCortex({"check", writeConfig(dir.path(), patchWith("footprint = 5e-17\n")).string()}, dir.path());
  EXPECT_EQ(tiny.exit_code, 0) << describe(tiny);
}

// The pair attraction's rates live in the engine and follow every hop; a resumed run
// must rebuild them to the last bit from the copies alone.
// An example shortened to end_time.
std::function<std::string(double)> shortened(const std::string& example, const std::string& end_key) {
  return [=](double end_time) {
    std::string text = readFile(sourceDir() / "examples" / example);
    text.replace(text.find(end_key), end_key.size(), fmt::format("end_time = {}", end_time));
    return text;
  };
}

// The fig. 3.3 example (one self-attracting species) and the two-species one (a cross
// interaction): whole and resumed runs agree copy for copy, and copies are conserved.
TEST(MembraneSpeciesRun, InteractingCopiesResumeBitIdentically) {
  const std::vector<std::tuple<std::string, std::string, std::vector<std::pair<std::string, int>>>> cases = {
      {"membrane_llps.toml", "end_time = 0.5", {{"P", 1500}}},
      {"membrane_llps_two_species.toml", "end_time = 0.3", {{"P", 1500}, {"C", 500}}}};
  for (const auto& [example, end_key, species] : cases) {
    TempDir dir;
    runWholeAndResumed(dir, shortened(example, end_key), 0.02, 0.04);
    if (::testing::Test::HasFatalFailure()) return;
    EXPECT_EQ(comparableSummary(dir / "A"), comparableSummary(dir / "B")) << example;
    const h5::File a = h5::File::openReadOnly(dir / "A" / "trajectory.h5");
    const h5::File b = h5::File::openReadOnly(dir / "B" / "trajectory.h5");
    ASSERT_EQ(a.children("/snapshots"), b.children("/snapshots"));
    for (const std::string& s : a.children("/snapshots"))
      for (const auto& [name, copies] : species) {
        const std::string g = "/snapshots/" + s + "/membranes/patch/species/" + name;
        EXPECT_EQ(a.readInt32(g), b.readInt32(g)) << example << " " << s;
        EXPECT_EQ(sum(a.readInt32(g)), copies) << example << " " << s;
      }
  }
}

TEST(MembraneSpeciesRun, ExampleIsAccepted) {
  TempDir dir;
  const RunResult r = runCortex({"check", (sourceDir() / "examples" / "membrane_proteins.toml").string()}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << describe(r);
  // Interacting copies may bind and unbind (the engine weighs unbinding by the pair energy).
  std::string binding = exampleText();
  replaceOnce(binding, "density = 0.0 ", "interaction = { height = 0.1, range = 18.0 }\ndensity = 0.0 ");
  const RunResult b = runCortex({"check", writeConfig(dir.path(), binding).string()}, dir.path());
  EXPECT_EQ(b.exit_code, 0) << describe(b);
}

// A sensing protein larger than the cells of its mesh (A_p = 400 nm² on the small vesicle's
// ~350 nm² cells): a second copy binding into a cell it then more than covers carries ~800
// k_BT of curvature energy and left at r e^{800}, an infinite rate: `check` accepted the
// config and the run stopped in its first window (exit 1). Above 13.8 k_BT the energy
// weighs binding instead (engine_base.hpp): the run goes on, and two copies never share a cell of that
// vesicle at a snapshot (such a pair lives ~1/(10⁶ r) = 0.1 µs; binding brings a copy to
// the vesicle every ~0.5 ms: 30,000 nm/s × 1.3·10⁵ nm² × 5·10⁻⁷ /nm³).
TEST(MembraneSpeciesRun, ASensingProteinLargerThanItsCellsBindsOneCopyPerCell) {
  TempDir dir;
  const RunResult r = runCortex({"run", (sourceDir() / "examples" / "curvature_sorting.toml").string(), "-o",
                                 (dir.path() / "out").string(), "--set", "membrane.0.species.0.curvature.area=400",
                                 "--set", "simulation.end_time=0.3"},
                                dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const h5::File f = h5::File::openReadOnly(dir.path() / "out" / "trajectory.h5");
  std::int64_t bound = 0;
  for (const std::string& s : f.children("/snapshots")) {
    const auto copies = f.readInt32("/snapshots/" + s + "/membranes/small/species/B_small");
    bound += sum(copies);
    for (std::size_t v = 0; v < copies.size(); ++v) EXPECT_LE(copies[v], 1) << "snapshot " << s << ", vertex " << v;
  }
  EXPECT_GT(bound, 10) << "too few copies bound to test";
}

// The same protein on a vesicle of R = 200 nm (cells ~320 nm² < A_p = 400 nm², κ_p = 1000
// pN·nm) binding from a 5,000-copy bulk: a second copy in a cell carries ~50 k_BT, so the
// bound copies sit one per cell, and their count is Σ_j y_j/(1 + y_j), y_j = k_on |C_j| c
// e^{−βV_j(0)}/k_off, V_j(0) = 2 A_p κ_eff H_j² (proteins.md), with c the bulk's
// remaining concentration (solved self-consistently). With the unbinding factor merely
// capped at 10⁶, a copy bound into an occupied cell hopped to an empty neighbour before
// leaving, a binding path with no way back: +8% here (391.6 against 362.0; more at slower
// k_off, and it grew with D). Capping with binding thinned by the excess keeps eq. 3.14's
// ratio: measured 353.8 (−2.3%, about 2 standard errors; some cells do hold two copies
// where the second costs little). Tolerance 5%.
TEST(MembraneSpeciesRun, ProteinsLargerThanTheirCellsBindAtTheOneCopyPerCellEquilibrium) {
  TempDir dir;
  const std::string text = R"([simulation]
seed = 1
end_time = 5.0
chemistry_window = 0.1
snapshot_interval = 0.1

[[membrane]]
name = "ves"
shape = "sphere"
center = [500.0, 500.0, 500.0]
radius = 200.0
mesh_size = 20.0
bending_modulus = 100.0

[[membrane.species]]
name = "P"
diffusion = 1.0e6

[membrane.species.curvature]
area = 400.0
bending_modulus = 1000.0

[compartments]
size = 250.0
shape = [4, 4, 4]

[[species]]
name = "G"
diffusion = 1.0e7
copies = 5000

[[reaction]]
equation = "G -> P"
rate = 320.0

[[reaction]]
equation = "P -> G"
rate = 1.0
)";
  const RunResult r = runConfig(writeConfig(dir.path(), text), dir / "out", {}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const h5::File f = h5::File::openReadOnly(dir.path() / "out" / "trajectory.h5");
  const std::vector<std::string> snapshots = f.children("/snapshots");
  ASSERT_EQ(snapshots.size(), 51u);
  // The closed form on the last snapshot's mesh (the sphere barely moves).
  const std::string g = "/snapshots/" + snapshots.back() + "/membranes/ves/";
  const std::vector<double> x = f.readDoubles(g + "vertices"), h = f.readDoubles(g + "mean_curvature");
  const std::vector<std::int32_t> t = f.readInt32(g + "triangles");
  std::vector<double> cell(h.size(), 0.0);
  for (std::size_t k = 0; k + 2 < t.size(); k += 3) {
    const Eigen::Map<const Vec3> a(&x[3 * t[k]]), b(&x[3 * t[k + 1]]), c(&x[3 * t[k + 2]]);
    const double third = (b - a).cross(c - a).norm() / 6.0;
    for (int i = 0; i < 3; ++i) cell[t[k + i]] += third;
  }
  const double kT = constants::kBoltzmann * 298.15, kappa_eff = 100.0 * 1000.0 / 1100.0;  // pN nm
  double bound = 0.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double c = (5000.0 - bound) / 1e9;  // copies/nm³ in the 1 µm³ box
    bound = 0.0;
    for (std::size_t v = 0; v < h.size(); ++v) {
      const double y = 320.0 * cell[v] * c * std::exp(-2.0 * 400.0 * kappa_eff * h[v] * h[v] / kT);
      bound += y / (1.0 + y);
    }
  }
  double measured = 0.0;  // over t >= 1 s
  for (std::size_t k = 10; k < snapshots.size(); ++k)
    measured += static_cast<double>(sum(f.readInt32("/snapshots/" + snapshots[k] + "/membranes/ves/species/P")));
  measured /= static_cast<double>(snapshots.size() - 10);
  EXPECT_NEAR(measured / bound, 1.0, 0.05) << "measured " << measured << ", closed form " << bound;
}

}  // namespace
}  // namespace cortex::cli_test
