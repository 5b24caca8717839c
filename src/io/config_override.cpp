#include "io/config_override.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <sstream>

#include "core/error.hpp"

namespace cortex {
namespace {

std::vector<std::string> split(const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  return parts;
}

// Whether all of `text` reads as a number (strtod's grammar), in range or not.
bool isNumeral(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

toml::node_view<toml::node> parseValue(const std::string& text, toml::table& holder, const std::string& where) {
  try {
    holder = toml::parse("v = " + text);
  } catch (const toml::parse_error& e) {
    // A numeral TOML refuses (1e400, past a double's range) is no bare word: taken as a
    // string, it was reported as "must be a number, got string".
    if (isNumeral(text))
      throw InputError(fmt::format("{}: {} does not read as a number (TOML: {})", where, text, e.description()));
    holder = toml::table{{"v", text}};  // a bare word: take it as a string
  }
  if (holder.size() != 1) holder = toml::table{{"v", text}};  // "1 # x = 2" and the like: not one value
  return holder["v"];
}

}  // namespace

void applyOverride(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  const std::string where = fmt::format("--set {}", assignment);
  if (eq == std::string::npos || eq == 0)
    throw InputError(fmt::format("{}: expected key.path=value", where));
  // A line break would end the TOML value and let the rest pass unread.
  for (const char c : assignment)
    if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
      throw InputError(fmt::format("--set: '{}...' holds a control character (line break, NUL...); give one "
                                   "key=value on one line",
                                   assignment.substr(0, assignment.find_first_of("\r\n"))));
  const std::vector<std::string> keys = split(assignment.substr(0, eq));
  toml::table holder;
  toml::node_view<toml::node> value = parseValue(assignment.substr(eq + 1), holder, where);

  toml::node* current = &root;
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    const std::string& k = keys[i];
    if (toml::table* t = current->as_table()) {
      if (!t->contains(k)) t->insert(k, toml::table{});
      current = t->get(k);
    } else if (toml::array* a = current->as_array()) {
      std::size_t index = 0;
      const auto [ptr, ec] = std::from_chars(k.data(), k.data() + k.size(), index);
      if (ec != std::errc() || ptr != k.data() + k.size())
        throw InputError(fmt::format("{}: '{}' must be an index into an array", where, k));
      if (index >= a->size())
        throw InputError(fmt::format("{}: index {} is out of range (the array has {} entries)", where,
                                     index, a->size()));
      current = a->get(index);
    } else {
      throw InputError(fmt::format("{}: '{}' is a value, not a table", where, keys[i - 1]));
    }
  }
  toml::table* parent = current->as_table();
  if (!parent && current->is_array())
    throw InputError(fmt::format("{}: an entry of an array of tables cannot be replaced by a value; set one of its "
                                 "keys ({}.radius=..., for example)",
                                 where, assignment.substr(0, eq)));
  if (!parent) throw InputError(fmt::format("{}: cannot set a key inside a non-table", where));
  parent->insert_or_assign(keys.back(), *value.node());
}

}  // namespace cortex
