#include "io/medyan_input.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace cortex::medyan {

namespace fs = std::filesystem;

namespace {

struct Token {
  std::string text;
  int line;
};

}  // namespace

std::string upperCase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::vector<Entry> parseFile(const fs::path& file) {
  const std::string text = readWholeFile(file, 64u << 20);
  const std::string name = file.filename().string();
  std::vector<Token> tokens;
  int line = 1;
  std::string word;
  int word_line = 1;
  auto flush = [&] {
    if (!word.empty()) tokens.push_back({word, word_line});
    word.clear();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '#' || c == ';') {  // comment to the end of the line
      flush();
      while (i < text.size() && text[i] != '\n') ++i;
      if (i < text.size()) ++line;
      tokens.push_back({"\n", line - 1});
      continue;
    }
    if (c == '\n') {
      flush();
      tokens.push_back({"\n", line});
      ++line;
    } else if (c == '(' || c == ')') {
      flush();
      tokens.push_back({std::string(1, c), line});
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      flush();
    } else {
      if (word.empty()) word_line = line;
      word += c;
    }
  }
  flush();

  std::vector<Entry> entries;
  auto start = [&](const Token& t) {
    Entry e;
    std::string key = t.text;
    const auto colon = key.find(':');
    if (colon != std::string::npos) {  // "KEY:" or "KEY:value"
      const std::string rest = key.substr(colon + 1);
      key = key.substr(0, colon);
      if (!rest.empty()) e.values.push_back(rest);
    }
    e.key = key;
    e.upper = upperCase(key);
    e.where = fmt::format("{}:{}", name, t.line);
    return e;
  };
  for (std::size_t i = 0; i < tokens.size();) {
    const Token& t = tokens[i];
    if (t.text == "\n") {
      ++i;
    } else if (t.text == ")") {
      throw InputError(fmt::format("{}:{}: ')' without a matching '('", name, t.line));
    } else if (t.text == "(") {
      const int open_line = t.line;
      std::size_t j = i + 1;
      while (j < tokens.size() && tokens[j].text == "\n") ++j;
      if (j >= tokens.size() || tokens[j].text == "(" || tokens[j].text == ")")
        throw InputError(fmt::format("{}:{}: '(' must be followed by a keyword", name, open_line));
      Entry e = start(tokens[j]);
      e.where = fmt::format("{}:{}", name, open_line);
      int depth = 1;
      for (++j; j < tokens.size() && depth > 0; ++j) {
        const std::string& s = tokens[j].text;
        if (s == "(") {
          ++depth;
          e.nested = true;
        } else if (s == ")") {
          --depth;
        } else if (s != "\n") {
          e.values.push_back(s);
        }
      }
      if (depth != 0) throw InputError(fmt::format("{}:{}: '(' is never closed", name, open_line));
      entries.push_back(std::move(e));
      i = j;
    } else {
      Entry e = start(t);
      std::size_t j = i + 1;
      for (; j < tokens.size() && tokens[j].text != "\n"; ++j) {
        if (tokens[j].text == "(" || tokens[j].text == ")")
          throw InputError(fmt::format("{}:{}: unexpected '{}' in a `KEY: value` line", name, tokens[j].line,
                                       tokens[j].text));
        e.values.push_back(tokens[j].text);
      }
      entries.push_back(std::move(e));
      i = j;
    }
  }
  return entries;
}

std::optional<double> toNumber(const std::string& s) {
  double v = 0;
  const char* end = s.data() + s.size();
  const auto [p, ec] = std::from_chars(s.data(), end, v);
  if (ec != std::errc() || p != end || !std::isfinite(v)) return std::nullopt;
  return v;
}

double number(const Entry& e, std::size_t i, const char* what) {
  if (i >= e.values.size()) throw InputError(fmt::format("{}: {}: {} is missing", e.where, e.key, what));
  const auto v = toNumber(e.values[i]);
  if (!v) throw InputError(fmt::format("{}: {}: {} must be a number, got '{}'", e.where, e.key, what, e.values[i]));
  return *v;
}

// Parses "[DELG:ID] [FILTYPE] A:T + B:T (->|<->) C:T + D:T p1 p2 ...".
Reaction parseReaction(const Entry& e, bool has_filament_type) {
  Reaction r;
  std::size_t i = 0;
  const auto& v = e.values;
  auto isRef = [](const std::string& s) { return s.find(':') != std::string::npos && !toNumber(s); };
  // The optional dissipation field DELGZERO:HRCDID comes first; it has a ':' but its
  // first part is a number.
  if (i < v.size() && v[i].find(':') != std::string::npos && toNumber(v[i].substr(0, v[i].find(':')))) {
    r.dissipation = true;
    ++i;
  }
  if (has_filament_type) {
    if (i >= v.size() || !toNumber(v[i]))
      throw InputError(fmt::format("{}: {}: expected the filament type (an integer) before the species", e.where, e.key));
    r.filament_type = static_cast<int>(*toNumber(v[i]));
    ++i;
  }
  auto side = [&](std::vector<Ref>& out) {
    while (true) {
      if (i >= v.size() || !isRef(v[i]))
        throw InputError(fmt::format("{}: {}: expected a species NAME:TYPE, got '{}'", e.where, e.key,
                                     i < v.size() ? v[i] : std::string("end of statement")));
      Ref ref;
      const std::string& s = v[i];
      const auto a = s.find(':');
      const auto b = s.find(':', a + 1);
      ref.name = s.substr(0, a);
      ref.type = upperCase(s.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1));
      if (b != std::string::npos) ref.pos = s.substr(b + 1);
      out.push_back(ref);
      ++i;
      if (i < v.size() && v[i] == "+") {
        ++i;
        continue;
      }
      break;
    }
  };
  side(r.reactants);
  if (i >= v.size() || (v[i] != "->" && v[i] != "<->"))
    throw InputError(fmt::format("{}: {}: expected '->' or '<->' after the reactants", e.where, e.key));
  r.reversible = v[i] == "<->";
  ++i;
  side(r.products);
  for (; i < v.size(); ++i) {
    const auto x = toNumber(v[i]);
    if (!x) break;
    r.params.push_back(*x);
  }
  return r;
}

}  // namespace cortex::medyan
