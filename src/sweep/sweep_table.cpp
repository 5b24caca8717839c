#include "sweep/sweep_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "io/hdf5_file.hpp"
#include "io/observables.hpp"

namespace cortex {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

SweepColumn numeric(std::string name, std::size_t rows) { return {std::move(name), false, std::vector<double>(rows, kNaN), {}}; }
SweepColumn text(std::string name, std::size_t rows) { return {std::move(name), true, {}, std::vector<std::string>(rows)}; }

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string quoted = "\"";
  for (const char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

ObservableRow summaryRow(const MemberOutcome& outcome) {
  if (outcome.status != MemberStatus::kOk) return {};
  ObservableRow row = observableRow(nlohmann::json::parse(outcome.summary));
  ObservableRow kept;
  for (std::size_t k = 0; k < row.names.size(); ++k)
    if (row.names[k] != "wall_seconds") {
      kept.names.push_back(row.names[k]);
      kept.values.push_back(row.values[k]);
    }
  return kept;
}

}  // namespace

SweepTable sweepTable(const SweepSpec& spec, const std::vector<std::int64_t>& seeds,
                      const std::vector<MemberOutcome>& outcomes) {
  const std::size_t n = spec.members.size();
  SweepTable table;
  table.rows = n;
  SweepColumn member = numeric("member", n), status = text("status", n), seed = numeric("seed", n),
              outdir = text("outdir", n), message = text("message", n);
  std::vector<SweepColumn> swept;
  for (std::size_t k = 0; k < spec.keys.size(); ++k)
    swept.push_back(spec.key_is_string[k] ? text(spec.keys[k], n) : numeric(spec.keys[k], n));
  std::vector<ObservableRow> rows;
  for (std::size_t i = 0; i < n; ++i) {
    member.numbers[i] = static_cast<double>(i);
    status.strings[i] = statusName(outcomes[i].status);
    seed.numbers[i] = static_cast<double>(seeds[i]);
    outdir.strings[i] = memberFolder(spec, i).string();
    message.strings[i] = outcomes[i].message;
    for (std::size_t k = 0; k < spec.keys.size(); ++k)
      if (const auto& v = spec.members[i].values[k]) {
        if (v->number)
          swept[k].numbers[i] = *v->number;
        else
          swept[k].strings[i] = v->text;
      }
    rows.push_back(summaryRow(outcomes[i]));
  }
  table.columns = {std::move(member), std::move(status), std::move(seed)};
  for (SweepColumn& c : swept) table.columns.push_back(std::move(c));
  table.columns.push_back(std::move(outdir));
  table.columns.push_back(std::move(message));
  const ObservableTable observed = tabulate(rows);
  for (std::size_t c = 0; c < observed.columns.size(); ++c) {
    SweepColumn column = numeric(observed.columns[c], n);
    for (std::size_t r = 0; r < n; ++r) column.numbers[r] = observed.values[r * observed.columns.size() + c];
    table.columns.push_back(std::move(column));
  }
  return table;
}

std::string sweepCsv(const SweepTable& table) {
  std::string csv;
  for (std::size_t c = 0; c < table.columns.size(); ++c) csv += (c ? "," : "") + csvField(table.columns[c].name);
  csv += '\n';
  for (std::size_t r = 0; r < table.rows; ++r) {
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      const SweepColumn& column = table.columns[c];
      if (c) csv += ',';
      if (column.is_string)
        csv += csvField(column.strings[r]);
      else
        csv += std::isnan(column.numbers[r]) ? std::string("nan") : fmt::format("{:.17g}", column.numbers[r]);
    }
    csv += '\n';
  }
  return csv;
}

std::string sweepHdf5Image(const SweepTable& table, const SweepSpec& spec) {
  h5::File file = h5::File::createInMemory("sweep.h5");
  std::vector<std::string> all, numeric_names;
  for (const SweepColumn& c : table.columns) {
    all.push_back(c.name);
    if (c.is_string)
      file.write("/strings/" + c.name, c.strings);
    else
      numeric_names.push_back(c.name);
  }
  std::vector<double> values(table.rows * numeric_names.size());
  std::size_t k = 0;
  for (const SweepColumn& c : table.columns) {
    if (c.is_string) continue;
    for (std::size_t r = 0; r < table.rows; ++r) values[r * numeric_names.size() + k] = c.numbers[r];
    ++k;
  }
  file.write("/table", values, {table.rows, numeric_names.size()});
  file.setAttribute("/table", "columns", joinColumns(numeric_names));
  file.setAttribute("/", "format", std::string("cortex sweep 1"));
  file.setAttribute("/", "cortex_version", std::string(CORTEX_VERSION));
  file.setAttribute("/", "columns", joinColumns(all));
  file.setAttribute("/", "sweep_file", spec.file.string());
  file.setAttribute("/", "sweep", spec.text);
  return file.image();
}

}  // namespace cortex
