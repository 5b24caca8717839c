// The observables table (issue 12): the summary's numeric leaves, one column each, and
// the table and CSV built from rows that may not share every column.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "io/observables.hpp"

namespace cortex {
namespace {

TEST(Observables, FlattensTheSummaryByPathWithMembranesByName) {
  const nlohmann::json summary = nlohmann::json::parse(R"({
    "seed": 7, "threads": 2, "time": 1.5, "wall_seconds": 3.0,
    "membranes": [{"name": "cell", "area": 10.0, "tension": null, "remesh": {"enabled": true}},
                  {"name": "nucleus", "area": 4.0}],
    "chemistry": {"species": {"A": 12, "B": 0}},
    "version": "x", "shape": [4, 4, 4]})");
  const ObservableRow row = observableRow(summary);
  const std::vector<std::string> expected = {"time",
                                             "chemistry.species.A",
                                             "chemistry.species.B",
                                             "membranes.cell.area",
                                             "membranes.cell.remesh.enabled",
                                             "membranes.cell.tension",
                                             "membranes.nucleus.area",
                                             "wall_seconds"};
  EXPECT_EQ(row.names, expected);  // seed, threads, strings and plain arrays left out
  ASSERT_EQ(row.values.size(), expected.size());
  EXPECT_EQ(row.values[0], 1.5);
  EXPECT_EQ(row.values[1], 12.0);
  EXPECT_EQ(row.values[4], 1.0);
  EXPECT_TRUE(std::isnan(row.values[5]));
  EXPECT_EQ(row.values[6], 4.0);
}

TEST(Observables, TabulatesTheUnionOfColumnsWithNaNWhereARowLacksOne) {
  const ObservableRow first{{"time", "a"}, {0.0, 1.0}};
  const ObservableRow second{{"time", "b", "a"}, {1.0, 5.0, 2.0}};
  const ObservableTable table = tabulate({first, second});
  EXPECT_EQ(table.columns, (std::vector<std::string>{"time", "a", "b"}));
  ASSERT_EQ(table.rows, 2u);
  EXPECT_EQ(table.values[0], 0.0);
  EXPECT_EQ(table.values[1], 1.0);
  EXPECT_TRUE(std::isnan(table.values[2]));
  EXPECT_EQ(table.values[3], 1.0);
  EXPECT_EQ(table.values[4], 2.0);
  EXPECT_EQ(table.values[5], 5.0);
  EXPECT_EQ(observablesCsv(table), "time,a,b\n0,1,nan\n1,2,5\n");
}

TEST(Observables, CsvKeepsEveryBitOfADouble) {
  const double third = 1.0 / 3.0;
  const ObservableTable table = tabulate({ObservableRow{{"x"}, {third}}});
  const std::string csv = observablesCsv(table);
  EXPECT_EQ(std::stod(csv.substr(csv.find('\n') + 1)), third);
}

TEST(Observables, ColumnNamesSurviveJoinAndSplit) {
  const std::vector<std::string> columns = {"time", "filaments.linkers.alpha-actinin", "x"};
  EXPECT_EQ(splitColumns(joinColumns(columns)), columns);
  EXPECT_TRUE(splitColumns("").empty());
  EXPECT_EQ(splitColumns("one"), std::vector<std::string>{"one"});
}

}  // namespace
}  // namespace cortex
