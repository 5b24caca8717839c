// Typed, validated access to one TOML table of the config, in one place: every getter
// names the file, line and dotted key in its error, and finish() rejects unknown keys.
#pragma once

#include <toml++/toml.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/schedule.hpp"
#include "core/types.hpp"

namespace cortex {

// Allowed interval of a number; open or closed at either end.
struct Range {
  double lo = -1e300, hi = 1e300;
  bool lo_open = false, hi_open = false;
  static Range positive() { return {0.0, 1e300, true, false}; }
  static Range nonNegative() { return {0.0, 1e300, false, false}; }
  bool contains(double v) const;
  std::string describe(double value) const;  // the bounds a value out of range missed
};

class ConfigReader {
 public:
  ConfigReader(const toml::table& table, std::string source, std::string path);

  bool has(const std::string& key) const;
  double number(const std::string& key, double fallback, Range range, const char* unit) const;
  double requiredNumber(const std::string& key, Range range, const char* unit) const;
  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  // A name of a membrane, species, type...: it names HDF5 groups, files and XDMF blocks,
  // so 1-64 letters, digits, '_' or '-', starting with a letter or '_'.
  std::string name(const std::string& key, const std::string& fallback) const;
  std::string choice(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& allowed) const;
  std::vector<double> numbers(const std::string& key, std::size_t count, Range range, const char* unit) const;
  // A number, or a list of [time, value] points with strictly increasing times.
  Schedule schedule(const std::string& key, std::optional<double> fallback, Range range, const char* unit) const;

  std::optional<ConfigReader> table(const std::string& key) const;
  std::vector<ConfigReader> tableArray(const std::string& key) const;

  // Throws InputError naming the first key that no getter asked for.
  void finish() const;
  // Throws InputError for key (e.g. a physically impossible combination).
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;
  const std::string& source() const { return source_; }
  std::string keyPath(const std::string& key) const;

 private:
  const toml::node& node(const std::string& key) const;
  std::string where(const toml::node* n) const;

  const toml::table& table_;
  std::string source_, path_;
  mutable std::set<std::string> used_;
};

}  // namespace cortex
