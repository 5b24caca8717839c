// The sweep table: one row per member in member order, the swept settings as columns
// named by their key paths, every summary number (but wall_seconds) as a column, failed
// members with their message, and the same bytes whatever order outcomes arrived in.
#include <gtest/gtest.h>

#include <cmath>

#include "app/cli_helpers.hpp"
#include "io/hdf5_file.hpp"
#include "io/observables.hpp"
#include "sweep/sweep_table.hpp"

namespace cortex {
namespace {

using cli_test::TempDir;

SweepSpec twoByTwo(const TempDir& dir) {
  return readSweepFile(cli_test::writeConfig(dir.path(), R"(base = "run.toml"
[grid]
"membrane.0.bending_modulus" = [10.0, 20.0]
"membrane.0.shape" = ["sphere", "ellipsoid"]
)",
                                             "sweep.toml"));
}

MemberOutcome ok(std::size_t index, double area, bool with_pressure) {
  nlohmann::json summary = {{"time", 0.5}, {"wall_seconds", 1.0 + index}, {"seed", 3}, {"threads", 1}};
  summary["membranes"] = {{{"name", "v"}, {"area", area}}};
  if (with_pressure) summary["membranes"][0]["pressure"] = 0.25;
  return {index, MemberStatus::kOk, "", summary.dump()};
}

TEST(SweepTable, OneRowPerMemberWithSweptKeysSummaryColumnsAndFailures) {
  TempDir dir;
  const SweepSpec spec = twoByTwo(dir);
  const std::vector<MemberOutcome> outcomes = {
      ok(0, 100.0, false), {1, MemberStatus::kFailed, "exit code 1: run failed: \"far\", at t = 0", ""},
      ok(2, 1.0 / 3.0, true), {3, MemberStatus::kPending, "", ""}};
  const SweepTable table = sweepTable(spec, {5, 6, 7, 8}, outcomes);
  std::vector<std::string> names;
  for (const SweepColumn& c : table.columns) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"member", "status", "seed", "membrane.0.bending_modulus",
                                             "membrane.0.shape", "outdir", "message", "time", "membranes.v.area",
                                             "membranes.v.pressure"}));
  const std::string csv = sweepCsv(table);
  EXPECT_EQ(csv,
            "member,status,seed,membrane.0.bending_modulus,membrane.0.shape,outdir,message,time,membranes.v.area,"
            "membranes.v.pressure\n"
            "0,ok,5,10,sphere,members/0000,,0.5,100,nan\n"
            "1,failed,6,10,ellipsoid,members/0001,\"exit code 1: run failed: \"\"far\"\", at t = 0\",nan,nan,nan\n"
            "2,ok,7,20,sphere,members/0002,,0.5,0.33333333333333331,0.25\n"
            "3,pending,8,20,ellipsoid,members/0003,,nan,nan,nan\n");
}

TEST(SweepTable, Hdf5HoldsTheNumbersAsOneTableAndTheStringsBesideIt) {
  TempDir dir;
  const SweepSpec spec = twoByTwo(dir);
  const std::vector<MemberOutcome> outcomes = {ok(0, 1.0, false), ok(1, 2.0, false), ok(2, 3.0, false),
                                               {3, MemberStatus::kFailed, "why", ""}};
  const SweepTable table = sweepTable(spec, {1, 1, 1, 1}, outcomes);
  const std::filesystem::path file = dir / "sweep.h5";
  cli_test::writeFile(file, sweepHdf5Image(table, spec));
  const h5::File h5 = h5::File::openReadOnly(file);
  h5::Shape shape;
  const std::vector<double> values = h5.readDoubles("/table", &shape);
  EXPECT_EQ(shape, (h5::Shape{4, 5}));
  EXPECT_EQ(splitColumns(h5.attributeString("/table", "columns")),
            (std::vector<std::string>{"member", "seed", "membrane.0.bending_modulus", "time", "membranes.v.area"}));
  EXPECT_EQ(values[2 * 5 + 4], 3.0);
  EXPECT_TRUE(std::isnan(values[3 * 5 + 4]));
  EXPECT_EQ(h5.readStrings("/strings/status"), (std::vector<std::string>{"ok", "ok", "ok", "failed"}));
  EXPECT_EQ(h5.readStrings("/strings/membrane.0.shape"),
            (std::vector<std::string>{"sphere", "ellipsoid", "sphere", "ellipsoid"}));
  EXPECT_EQ(h5.readStrings("/strings/message")[3], "why");
  EXPECT_EQ(splitColumns(h5.attributeString("/", "columns")).size(), 9u);
  EXPECT_EQ(h5.attributeString("/", "format"), "cortex sweep 1");
  EXPECT_EQ(h5.attributeString("/", "sweep"), spec.text);
}

}  // namespace
}  // namespace cortex
