// End-to-end: a small actomyosin box run through the CLI writes its filaments, linkers and
// motors to trajectory.h5 / trajectory.xdmf / summary.json consistently, conserves actin
// monomers between the G pool and the filaments, and resumes bit-identically.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "app/cli_helpers.hpp"

namespace cortex::cli_test {
namespace {

constexpr int kInitialG = 3000;
constexpr int kInitialFilaments = 20;
constexpr std::int64_t kMonomersPerFilament = 40;  // 108 nm / 2.7 nm

// Grows, binds linkers and motors within 0.2 s; no nucleation or branching, so every G
// copy is either free or in a filament.
std::string actomyosinConfig(double end_time) {
  return fmt::format(R"(
[simulation]
seed = 11
end_time = {}
chemistry_window = 0.025
snapshot_interval = 0.05

[mechanics]
force_tolerance = 1.0

[compartments]
size = 500.0
shape = [2, 2, 1]

[[species]]
name = "G"
diffusion = 2.0e7
copies = {}

[[species]]
name = "AA"
diffusion = 2.0e6
copies = 1000

[[species]]
name = "MII"
diffusion = 2.0e5
copies = 60

[[filament_type]]
name = "actin"
monomer_species = "G"
plus_on = 11.6
plus_off = 1.4
minus_on = 1.3
minus_off = 0.8

[[filaments]]
count = {}
length = 108.0
region = {{ min = [400.0, 400.0, 150.0], max = [600.0, 600.0, 350.0] }}

[boundary]
shape = "box"

[[linker]]
name = "alpha-actinin"
species = "AA"
on_rate = 5.0
off_rate = 0.3

[[motor]]
name = "myosin"
species = "MII"
on_rate = 20.0
off_rate = 1.7
walk_rate = 0.2
)",
                     end_time, kInitialG, kInitialFilaments);
}

std::int64_t sum(const std::vector<std::int32_t>& v) { return std::accumulate(v.begin(), v.end(), std::int64_t{0}); }
std::int64_t sum(const std::vector<std::int64_t>& v) { return std::accumulate(v.begin(), v.end(), std::int64_t{0}); }

const char* const kFilamentDatasets[] = {
    "beads",   "offsets",         "ids",          "types",          "lengths",     "monomers",
    "cylinders", "cylinder_filament", "linkers",  "linker_types",   "linker_tensions", "linker_cells",
    "motors",  "motor_types",     "motor_tensions", "motor_cells",  "branch_points"};

TEST(FilamentOutputs, TrajectorySummaryAndLogAreConsistent) {
  TempDir dir;
  const RunResult r = runConfig(writeConfig(dir.path(), actomyosinConfig(0.2)), dir / "out", {}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const nlohmann::json summary = readJson(dir / "out" / "summary.json");
  const nlohmann::json& fil = summary["filaments"];
  const h5::File file = h5::File::openReadOnly(dir / "out" / "trajectory.h5");
  const std::vector<std::string> snapshots = file.children("/snapshots");
  ASSERT_EQ(snapshots.size(), 5u);  // t = 0, 0.05, ..., 0.2

  std::int64_t total_monomers = -1;
  for (const std::string& s : snapshots) {
    SCOPED_TRACE("snapshot " + s);
    const std::string g = "/snapshots/" + s + "/filaments/";
    h5::Shape beads_shape, offsets_shape, cyl_shape, linkers_shape, motors_shape, branch_shape;
    const std::vector<double> beads = file.readDoubles(g + "beads", &beads_shape);
    const std::vector<std::int64_t> offsets = file.readInt64(g + "offsets", &offsets_shape);
    const std::vector<std::int32_t> cylinders = file.readInt32(g + "cylinders", &cyl_shape);
    const std::vector<double> linkers = file.readDoubles(g + "linkers", &linkers_shape);
    const std::vector<double> motors = file.readDoubles(g + "motors", &motors_shape);
    file.readDoubles(g + "branch_points", &branch_shape);
    const std::vector<std::int64_t> ids = file.readInt64(g + "ids");
    const std::vector<double> lengths = file.readDoubles(g + "lengths");
    const std::vector<std::int64_t> monomers = file.readInt64(g + "monomers");

    // Storage types and shapes.
    EXPECT_EQ(h5DatasetType(dir / "out" / "trajectory.h5", g + "beads").bytes, 8u);
    EXPECT_EQ(h5DatasetType(dir / "out" / "trajectory.h5", g + "offsets").bytes, 8u);
    EXPECT_EQ(h5DatasetType(dir / "out" / "trajectory.h5", g + "ids").bytes, 8u);
    EXPECT_EQ(h5DatasetType(dir / "out" / "trajectory.h5", g + "types").bytes, 4u);
    EXPECT_EQ(h5DatasetType(dir / "out" / "trajectory.h5", g + "cylinders").bytes, 4u);
    const auto k = static_cast<std::int64_t>(beads.size() / 3);
    const auto f = static_cast<std::int64_t>(ids.size());
    EXPECT_EQ(beads_shape, (h5::Shape{static_cast<hsize_t>(k), 3}));
    EXPECT_EQ(f, kInitialFilaments);  // no nucleation, and filaments are never removed
    ASSERT_EQ(offsets_shape, (h5::Shape{static_cast<hsize_t>(f + 1)}));
    EXPECT_EQ(offsets.front(), 0);
    EXPECT_EQ(offsets.back(), k);
    for (std::int64_t i = 0; i < f; ++i) {
      EXPECT_EQ(ids[i], i);
      EXPECT_GE(offsets[i + 1] - offsets[i], 2);
    }
    ASSERT_EQ(cyl_shape.size(), 2u);
    EXPECT_EQ(static_cast<std::int64_t>(cyl_shape[0]), k - f);
    EXPECT_EQ(cyl_shape[1], 2u);
    ASSERT_EQ(linkers_shape.size(), 3u);
    EXPECT_EQ(linkers_shape[1], 2u);
    EXPECT_EQ(linkers_shape[2], 3u);
    EXPECT_EQ(file.shape(g + "linker_types"), h5::Shape{linkers_shape[0]});
    ASSERT_EQ(motors_shape.size(), 3u);
    EXPECT_EQ(file.shape(g + "motor_types"), h5::Shape{motors_shape[0]});
    EXPECT_EQ(branch_shape, (h5::Shape{0, 3}));

    // Cylinders join consecutive beads of one filament; their lengths add up per filament.
    std::vector<double> from_beads(static_cast<std::size_t>(f), 0.0);
    std::int64_t owner = 0;
    for (std::size_t c = 0; c < cylinders.size() / 2; ++c) {
      const std::int32_t a = cylinders[2 * c], b = cylinders[2 * c + 1];
      ASSERT_EQ(b, a + 1);
      while (owner < f && a >= offsets[owner + 1]) ++owner;
      ASSERT_LT(b, offsets[owner + 1]);
      from_beads[owner] += std::hypot(beads[3 * b] - beads[3 * a], beads[3 * b + 1] - beads[3 * a + 1],
                                    beads[3 * b + 2] - beads[3 * a + 2]);
    }
    for (std::int64_t i = 0; i < f; ++i) EXPECT_NEAR(lengths[i], from_beads[i], 1e-9 * lengths[i]);

    // Monomers are conserved between the free G pool and the filaments.
    const std::int64_t now = sum(file.readInt32("/snapshots/" + s + "/compartments/species/G")) + sum(monomers);
    if (s == snapshots.front()) {
      EXPECT_EQ(sum(monomers), kInitialFilaments * kMonomersPerFilament);
      total_monomers = now;
      EXPECT_EQ(total_monomers, kInitialG + kInitialFilaments * kMonomersPerFilament);
    }
    EXPECT_EQ(now, total_monomers);

    // The last snapshot is the summarized state.
    if (s == snapshots.back()) {
      EXPECT_EQ(fil["count"].get<std::int64_t>(), f);
      EXPECT_EQ(fil["beads"].get<std::int64_t>(), k);
      EXPECT_EQ(fil["monomers"].get<std::int64_t>(), sum(monomers));
      EXPECT_GT(fil["linkers"]["alpha-actinin"].get<std::int64_t>(), 0);
      EXPECT_EQ(fil["linkers"]["alpha-actinin"].get<std::int64_t>(), static_cast<std::int64_t>(linkers_shape[0]));
      EXPECT_GT(fil["motors"]["myosin"].get<std::int64_t>(), 0);
      EXPECT_EQ(fil["motors"]["myosin"].get<std::int64_t>(), static_cast<std::int64_t>(motors_shape[0]));
      const double total = std::accumulate(from_beads.begin(), from_beads.end(), 0.0);
      EXPECT_NEAR(fil["total_length"].get<double>(), total, 1e-9 * total);
      EXPECT_NEAR(fil["mean_length"].get<double>(), total / f, 1e-9 * total);
      // Growth happened: more than the initial 108 nm per filament.
      EXPECT_GT(total, 108.0 * f);
      // Bound linkers sit between two binding sites: their length is within the binding range,
      // give or take the relaxation since binding.
      for (std::size_t i = 0; i < linkers.size() / 6; ++i) {
        const double* e = &linkers[6 * i];
        const double d = std::hypot(e[3] - e[0], e[4] - e[1], e[5] - e[2]);
        EXPECT_GT(d, 20.0);
        EXPECT_LT(d, 50.0);
      }
      // And the free copies plus the bound ones are the initial ones.
      EXPECT_EQ(summary["chemistry"]["species"]["AA"].get<std::int64_t>() + static_cast<std::int64_t>(linkers_shape[0]),
                1000);
      EXPECT_EQ(summary["chemistry"]["species"]["MII"].get<std::int64_t>() + static_cast<std::int64_t>(motors_shape[0]),
                60);
    }
  }
  EXPECT_EQ(summary["chemistry"]["species"]["G"].get<std::int64_t>() + fil["monomers"].get<std::int64_t>(),
            total_monomers);

  // Energies: one entry per filament term, and the total is their sum.
  const nlohmann::json& energy = fil["energy"];
  double terms = 0.0;
  for (const char* name : {"stretching", "bending", "excluded_volume", "boundary", "linkers", "motors", "branching"}) {
    ASSERT_TRUE(energy.contains(name)) << name;
    terms += energy[name].get<double>();
  }
  EXPECT_NEAR(energy["total"].get<double>(), terms, 1e-9 * std::abs(terms));
  EXPECT_GT(energy["bending"].get<double>(), 0.0);  // the filaments are not straight after growth
  EXPECT_TRUE(fil["branches"].is_object());

  // XDMF: a filament grid per snapshot; linker and motor grids only where some are bound.
  const std::string xdmf = readFile(dir / "out" / "trajectory.xdmf");
  EXPECT_NE(xdmf.find("snapshots/000000.h5:/filaments/cylinders"), std::string::npos);
  EXPECT_NE(xdmf.find("TopologyType=\"Polyline\" NodesPerElement=\"2\""), std::string::npos);
  EXPECT_EQ(xdmf.find("/snapshots/000000/filaments/linkers"), std::string::npos);
  EXPECT_NE(xdmf.find("snapshots/000004.h5:/filaments/linkers"), std::string::npos);

  // The log has a filament line per snapshot.
  const std::string log = readFile(dir / "out" / "cortex.log");
  std::size_t lines = 0;
  for (std::size_t at = log.find(", filaments: 20,"); at != std::string::npos; at = log.find(", filaments: 20,", at + 1))
    ++lines;
  EXPECT_EQ(lines, snapshots.size());
}

TEST(FilamentOutputs, ResumedRunWritesTheSameFilaments) {
  TempDir dir;
  runWholeAndResumed(dir, actomyosinConfig, 0.1, 0.2, {"--threads", "1"});
  if (::testing::Test::HasFatalFailure()) return;
  EXPECT_EQ(comparableSummary(dir / "A")["filaments"], comparableSummary(dir / "B")["filaments"]);
  EXPECT_EQ(comparableSummary(dir / "A"), comparableSummary(dir / "B"));
  const h5::File a = h5::File::openReadOnly(dir / "A" / "trajectory.h5");
  const h5::File b = h5::File::openReadOnly(dir / "B" / "trajectory.h5");
  ASSERT_EQ(a.children("/snapshots"), b.children("/snapshots"));
  for (const std::string& s : a.children("/snapshots")) {
    for (const char* name : kFilamentDatasets) {
      const std::string path = "/snapshots/" + s + "/filaments/" + name;
      h5::Shape sa, sb;
      // Doubles compared with ==: a resumed run must be bit-identical.
      EXPECT_EQ(a.readDoubles(path, &sa), b.readDoubles(path, &sb)) << path;
      EXPECT_EQ(sa, sb) << path;
    }
  }
  expectSameCompartmentCounts(dir / "A" / "trajectory.h5", dir / "B" / "trajectory.h5", {"G", "AA", "MII"});
  // The resumed run's XDMF still indexes the snapshots written before the restart.
  const std::string xdmf = readFile(dir / "B" / "trajectory.xdmf");
  EXPECT_EQ(xdmf, readFile(dir / "A" / "trajectory.xdmf"));
}

// Motors with heads: the head counts drawn at binding and the event counters are in the
// checkpoint, so a resumed run continues identically.
TEST(FilamentOutputs, ResumedRunWithMotorHeadsIsIdentical) {
  TempDir dir;
  runWholeAndResumed(
      dir, [](double end) { return actomyosinConfig(end) + "heads_min = 15\nheads_max = 30\n"; }, 0.1, 0.2,
      {"--threads", "1"});
  if (::testing::Test::HasFatalFailure()) return;
  const auto a = comparableSummary(dir / "A");
  EXPECT_EQ(a, comparableSummary(dir / "B"));
  EXPECT_GT(a["filaments"]["events"]["motor_bindings"].get<std::int64_t>(), 0);
  const h5::File fa = h5::File::openReadOnly(dir / "A" / "checkpoint.h5");
  const std::vector<std::int64_t> heads = fa.readInt64("/filaments/motors/heads");
  ASSERT_FALSE(heads.empty());
  for (std::int64_t h : heads) {
    EXPECT_GE(h, 15);
    EXPECT_LE(h, 30);
  }
}

// A filament run is a function of (config, seed, thread count) — and here not even of the
// thread count: same seed, 1 or 2 threads, identical summary and filament datasets; a
// different seed differs.
TEST(FilamentOutputs, SameSeedIdenticalAcrossThreadCounts) {
  TempDir dir;
  const fs::path config = writeConfig(dir.path(), actomyosinConfig(0.2));
  for (const auto& [o, args] : {std::pair{"t1", std::vector<std::string>{"--threads", "1"}},
                                std::pair{"t2", std::vector<std::string>{"--threads", "2"}},
                                std::pair{"s2", std::vector<std::string>{"--threads", "1", "--seed", "99"}}}) {
    const RunResult r = runConfig(config, dir / o, args, dir.path(), {"OMP_WAIT_POLICY=passive"});
    ASSERT_EQ(r.exit_code, 0) << describe(r);
  }
  EXPECT_EQ(comparableSummary(dir / "t1", {"wall_seconds", "threads"}),
            comparableSummary(dir / "t2", {"wall_seconds", "threads"}));
  const h5::File a = h5::File::openReadOnly(dir / "t1" / "trajectory.h5");
  const h5::File b = h5::File::openReadOnly(dir / "t2" / "trajectory.h5");
  const h5::File c = h5::File::openReadOnly(dir / "s2" / "trajectory.h5");
  const std::string last = "/snapshots/" + a.children("/snapshots").back() + "/filaments/beads";
  EXPECT_EQ(a.readDoubles(last), b.readDoubles(last));
  EXPECT_NE(a.readDoubles(last), c.readDoubles(last));
}

// A run without filaments writes no filaments group and keeps the zero block in the summary.
TEST(FilamentOutputs, NoFilamentsNoGroup) {
  TempDir dir;
  const RunResult r = runConfig(writeConfig(dir.path(), R"(
[simulation]
end_time = 0.02
chemistry_window = 0.01
snapshot_interval = 0.01

[compartments]
size = 500.0
shape = [1, 1, 1]

[[species]]
name = "A"
diffusion = 1.0e6
copies = 10
)"),
                                dir / "out", {}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  const h5::File file = h5::File::openReadOnly(dir / "out" / "trajectory.h5");
  EXPECT_FALSE(file.exists("/snapshots/000000/filaments"));
  const nlohmann::json fil = readJson(dir / "out" / "summary.json")["filaments"];
  EXPECT_EQ(fil["count"].get<int>(), 0);
  EXPECT_EQ(fil["total_length"].get<double>(), 0.0);
  EXPECT_EQ(fil["energy"]["total"].get<double>(), 0.0);
}

}  // namespace
}  // namespace cortex::cli_test
