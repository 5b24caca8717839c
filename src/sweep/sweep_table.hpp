// The sweep's results as one table, one row per member in member order: who it is
// (member, status, seed, the swept settings, its folder, why it failed) and every number
// of its summary.json (docs/sweep.md). Written as sweep.csv and sweep.h5; a pure function
// of the members' results, so the same sweep gives the same bytes of CSV however and in
// whatever order its members ran.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sweep/member_run.hpp"
#include "sweep/sweep_spec.hpp"

namespace cortex {

struct SweepColumn {
  std::string name;
  bool is_string = false;
  std::vector<double> numbers;       // rows, when numeric (NaN where absent)
  std::vector<std::string> strings;  // rows, when strings (empty where absent)
};

struct SweepTable {
  std::vector<SweepColumn> columns;
  std::size_t rows = 0;
};

// `seeds` and `outcomes` are per member, in member order. The summaries' wall_seconds
// is left out: it is the one number that differs between equal runs.
SweepTable sweepTable(const SweepSpec& spec, const std::vector<std::int64_t>& seeds,
                      const std::vector<MemberOutcome>& outcomes);

// A header of column names, then one line per row: numbers to 17 significant digits
// ("nan" where absent), strings quoted as RFC 4180 asks when they hold a comma, a quote
// or a line break.
std::string sweepCsv(const SweepTable& table);

// The HDF5 file's bytes: /table float64 (rows × numeric columns) with attribute
// `columns`, each string column as /strings/<name>, root attributes describing the sweep.
std::string sweepHdf5Image(const SweepTable& table, const SweepSpec& spec);

}  // namespace cortex
