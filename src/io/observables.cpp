#include "io/observables.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <unordered_map>

namespace cortex {
namespace {

void flatten(const nlohmann::json& j, const std::string& path, ObservableRow& row) {
  const auto add = [&](double v) {
    row.names.push_back(path);
    row.values.push_back(v);
  };
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) flatten(it.value(), path.empty() ? it.key() : path + "." + it.key(), row);
  } else if (j.is_array()) {
    // Objects with a name (membranes) are keyed by it; other arrays are not observables.
    for (const nlohmann::json& item : j)
      if (item.is_object() && item.contains("name") && item["name"].is_string())
        flatten(item, path + "." + item["name"].get<std::string>(), row);
  } else if (j.is_boolean()) {
    add(j.get<bool>() ? 1.0 : 0.0);
  } else if (j.is_number()) {
    add(j.get<double>());
  } else if (j.is_null()) {
    add(std::numeric_limits<double>::quiet_NaN());
  }
}

}  // namespace

ObservableRow observableRow(const nlohmann::json& summary) {
  nlohmann::json copy = summary;
  for (const char* constant : {"seed", "threads"}) copy.erase(constant);
  ObservableRow row;
  // time first: the column a reader looks for.
  if (copy.contains("time")) {
    row.names.push_back("time");
    row.values.push_back(copy["time"].get<double>());
    copy.erase("time");
  }
  flatten(copy, "", row);
  return row;
}

ObservableTable tabulate(const std::vector<ObservableRow>& rows) {
  ObservableTable table;
  std::unordered_map<std::string, std::size_t> column;
  for (const ObservableRow& row : rows)
    for (const std::string& name : row.names)
      if (column.emplace(name, table.columns.size()).second) table.columns.push_back(name);
  table.rows = rows.size();
  table.values.assign(table.rows * table.columns.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t k = 0; k < rows[r].names.size(); ++k)
      table.values[r * table.columns.size() + column.at(rows[r].names[k])] = rows[r].values[k];
  return table;
}

std::string observablesCsv(const ObservableTable& table) {
  std::string csv = joinColumns(table.columns) + "\n";
  const std::size_t m = table.columns.size();
  for (std::size_t r = 0; r < table.rows; ++r) {
    for (std::size_t c = 0; c < m; ++c) {
      const double v = table.values[r * m + c];
      if (c) csv += ',';
      csv += std::isnan(v) ? std::string("nan") : fmt::format("{:.17g}", v);
    }
    csv += '\n';
  }
  return csv;
}

std::string joinColumns(const std::vector<std::string>& columns) {
  std::string joined;
  for (std::size_t i = 0; i < columns.size(); ++i) joined += (i ? "," : "") + columns[i];
  return joined;
}

std::vector<std::string> splitColumns(const std::string& joined) {
  std::vector<std::string> columns;
  std::size_t start = 0;
  while (start <= joined.size() && !joined.empty()) {
    const std::size_t comma = joined.find(',', start);
    columns.push_back(joined.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return columns;
}

}  // namespace cortex
