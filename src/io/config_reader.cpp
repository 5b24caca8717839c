#include "io/config_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace cortex {
namespace {

// Levenshtein distance, to suggest the key a user probably meant.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

bool Range::contains(double v) const {
  return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string Range::describe(double value) const {
  // The default bounds (±1e300) are named only when the value is beyond them: "must be
  // >= 0, got 7.6e+301" stated the wrong problem.
  const bool has_lo = lo > -1e299 || value < lo, has_hi = hi < 1e299 || value > hi;
  if (has_lo && has_hi)
    return fmt::format("in {}{:g}, {:g}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]");
  if (has_lo) return fmt::format("{} {:g}", lo_open ? ">" : ">=", lo);
  if (has_hi) return fmt::format("{} {:g}", hi_open ? "<" : "<=", hi);
  return "finite";
}

ConfigReader::ConfigReader(const toml::table& table, std::string source, std::string path)
    : table_(table), source_(std::move(source)), path_(std::move(path)) {}

std::string ConfigReader::keyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

std::string ConfigReader::where(const toml::node* n) const {
  if (n && n->source().begin.line > 0) return fmt::format("{}:{}", source_, n->source().begin.line);
  return source_;
}

void ConfigReader::fail(const std::string& key, const std::string& problem) const {
  const toml::node* n = table_.get(key);
  throw InputError(fmt::format("{}: {}: {}", where(n ? n : &table_), keyPath(key), problem));
}

bool ConfigReader::has(const std::string& key) const {
  used_.insert(key);
  return table_.contains(key);
}

const toml::node& ConfigReader::node(const std::string& key) const {
  used_.insert(key);
  const toml::node* n = table_.get(key);
  if (!n) {
    std::string hint;
    for (const auto& [k, unused] : table_)
      if (editDistance(std::string(k.str()), key) <= 2) hint = fmt::format(" (found \"{}\": misspelt?)", k.str());
    fail(key, "is required but missing" + hint);
  }
  return *n;
}

namespace {
double asFiniteNumber(const toml::node& n, const ConfigReader& r, const std::string& key) {
  std::optional<double> v = n.is_integer() ? std::optional<double>(static_cast<double>(*n.value<std::int64_t>()))
                                           : n.value_exact<double>();
  if (!v) {
    std::ostringstream type;
    type << n.type();
    r.fail(key, "must be a number, got " + type.str());
  }
  if (!std::isfinite(*v)) r.fail(key, fmt::format("must be finite, got {}", *v));
  return *v;
}
}  // namespace

double ConfigReader::requiredNumber(const std::string& key, Range range, const char* unit) const {
  const double v = asFiniteNumber(node(key), *this, key);
  if (!range.contains(v)) fail(key, fmt::format("must be {} {}, got {:g}", range.describe(v), unit, v));
  return v;
}

double ConfigReader::number(const std::string& key, double fallback, Range range, const char* unit) const {
  return has(key) ? requiredNumber(key, range, unit) : fallback;
}

std::int64_t ConfigReader::integer(const std::string& key, std::int64_t fallback, std::int64_t lo,
                                   std::int64_t hi) const {
  if (!has(key)) return fallback;
  const auto v = node(key).value_exact<std::int64_t>();
  if (!v) fail(key, "must be an integer");
  if (*v < lo || *v > hi) fail(key, fmt::format("must be in [{}, {}], got {}", lo, hi, *v));
  return *v;
}

bool ConfigReader::boolean(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const auto v = node(key).value_exact<bool>();
  if (!v) fail(key, "must be true or false");
  return *v;
}

std::string ConfigReader::string(const std::string& key, const std::string& fallback) const {
  if (!has(key)) return fallback;
  const auto v = node(key).value_exact<std::string>();
  if (!v) fail(key, "must be a string");
  return *v;
}

namespace {
// The text with anything but printable ASCII shown as \xNN (a NUL must not reach a message).
std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f)
      out += c;
    else
      out += fmt::format("\\x{:02x}", u);
  }
  return out;
}
}  // namespace

std::string ConfigReader::name(const std::string& key, const std::string& fallback) const {
  const std::string v = string(key, fallback);
  const auto allowed = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; };
  const bool ok = !v.empty() && v.size() <= 64 && (std::isalpha(static_cast<unsigned char>(v[0])) || v[0] == '_') &&
                  std::all_of(v.begin(), v.end(), allowed);
  if (!ok)
    fail(key, fmt::format("must be 1-64 letters, digits, '_' or '-', starting with a letter or '_' (it names "
                          "HDF5 groups and files), got \"{}\"",
                          printable(v)));
  return v;
}

std::string ConfigReader::choice(const std::string& key, const std::string& fallback,
                                 const std::vector<std::string>& allowed) const {
  const std::string v = string(key, fallback);
  for (const auto& a : allowed)
    if (a == v) return v;
  fail(key, fmt::format("must be one of \"{}\", got \"{}\"", fmt::join(allowed, "\", \""), v));
}

std::vector<double> ConfigReader::numbers(const std::string& key, std::size_t count, Range range,
                                          const char* unit) const {
  const toml::array* a = node(key).as_array();
  if (!a || a->size() != count) fail(key, fmt::format("must be a list of {} numbers", count));
  std::vector<double> out;
  for (const toml::node& n : *a) {
    const double v = asFiniteNumber(n, *this, key);
    if (!range.contains(v)) fail(key, fmt::format("entries must be {} {}, got {:g}", range.describe(v), unit, v));
    out.push_back(v);
  }
  return out;
}

Schedule ConfigReader::schedule(const std::string& key, std::optional<double> fallback, Range range,
                                const char* unit) const {
  if (!has(key)) return fallback ? Schedule(*fallback) : Schedule();
  const toml::node& n = node(key);
  if (!n.is_array()) return Schedule(requiredNumber(key, range, unit));
  std::vector<std::pair<double, double>> points;
  for (const toml::node& p : *n.as_array()) {
    const toml::array* pair = p.as_array();
    if (!pair || pair->size() != 2)
      fail(key, "must be a number or a list of [time, value] pairs, e.g. [[0.0, 1.0], [10.0, 0.6]]");
    const double t = asFiniteNumber(*pair->get(0), *this, key);
    const double v = asFiniteNumber(*pair->get(1), *this, key);
    if (!range.contains(v)) fail(key, fmt::format("values must be {} {}, got {:g}", range.describe(v), unit, v));
    if (!points.empty() && t <= points.back().first)
      fail(key, fmt::format("times must increase strictly ({:g} s follows {:g} s)", t, points.back().first));
    points.emplace_back(t, v);
  }
  if (points.empty()) fail(key, "schedule has no points");
  return Schedule(std::move(points));
}

std::optional<ConfigReader> ConfigReader::table(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  const toml::table* t = node(key).as_table();
  if (!t) fail(key, "must be a table");
  return ConfigReader(*t, source_, keyPath(key));
}

std::vector<ConfigReader> ConfigReader::tableArray(const std::string& key) const {
  std::vector<ConfigReader> out;
  if (!has(key)) return out;
  const toml::array* a = node(key).as_array();
  if (!a || !a->is_array_of_tables()) fail(key, fmt::format("must be an array of tables ([[{}]])", key));
  for (std::size_t i = 0; i < a->size(); ++i)
    out.emplace_back(*a->get(i)->as_table(), source_, keyPath(fmt::format("{}.{}", key, i)));
  return out;
}

void ConfigReader::finish() const {
  for (const auto& [key, n] : table_) {
    const std::string k(key.str());
    if (!used_.count(k))
      throw InputError(fmt::format("{}: {}: unknown key (misspelt?)", where(&n), keyPath(k)));
  }
}

}  // namespace cortex
