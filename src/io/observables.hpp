// Observables over time: the scalars of summary.json at every snapshot, one column each,
// named by their path in the summary ("membranes.vesicle.energy.bending",
// "chemistry.species.A", "filaments.total_length", ...). The table lives in trajectory.h5
// (/observables) and in observables.csv (docs/output.md); the last snapshot's row holds
// the values summary.json reports (wall_seconds aside: the summary is written later).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/frame.hpp"

namespace cortex {

// The numeric leaves of a summary, depth first in key order. Membranes are keyed by
// name; booleans read 0/1, null NaN; strings and other arrays are left out, as are the
// run's constants (seed, threads).
ObservableRow observableRow(const nlohmann::json& summary);

// Rows as one table: the columns are the union of the rows' names in order of first
// appearance (a resumed run may add a term), NaN where a row lacks one.
struct ObservableTable {
  std::vector<std::string> columns;
  std::vector<double> values;  // rows × columns, row-major
  std::size_t rows = 0;
};
ObservableTable tabulate(const std::vector<ObservableRow>& rows);

// CSV text: a header line of column names, then one line per row (%.17g; NaN as "nan").
std::string observablesCsv(const ObservableTable& table);

// Column names joined by commas (names hold no comma: they are validated identifiers and
// summary keys), as stored in the HDF5 attribute "columns".
std::string joinColumns(const std::vector<std::string>& columns);
std::vector<std::string> splitColumns(const std::string& joined);

}  // namespace cortex
