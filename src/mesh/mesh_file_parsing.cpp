#include "mesh/mesh_file_parsing.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <system_error>

#include <fmt/format.h>

#include "core/error.hpp"

namespace cortex::mesh_file_detail {

void fail(const Path& path, const std::string& where, const std::string& problem) {
  const char* separator = where.empty() ? "" : ":";
  throw InputError(fmt::format("{}{}{}: {}", path.string(), separator, where, problem));
}

std::string readAll(const Path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open mesh file", path.string()));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    std::string_view line = text.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    text.remove_prefix(std::min(end + 1, text.size()));
  }
  return lines;
}

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  const char* blanks = " \t\r\f\v";
  for (std::size_t pos = line.find_first_not_of(blanks); pos != std::string_view::npos;) {
    const std::size_t end = std::min(line.find_first_of(blanks, pos), line.size());
    words.push_back(line.substr(pos, end - pos));
    pos = line.find_first_not_of(blanks, end);
  }
  return words;
}

std::optional<double> parseNumber(std::string_view word) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

void addPolygon(TriangleSoup& soup, const std::vector<long long>& polygon,
                std::size_t vertex_count, const Path& path, const std::string& where) {
  if (polygon.size() < 3) fail(path, where, "face has fewer than 3 vertices");
  for (long long v : polygon) {
    if (v < 0 || v >= static_cast<long long>(vertex_count)) {
      fail(path, where,
           fmt::format("vertex index {} out of range (the file has {} vertices)", v, vertex_count));
    }
  }
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    const Tri t{Index(polygon[0]), Index(polygon[k]), Index(polygon[k + 1])};
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) fail(path, where, "face repeats a vertex");
    soup.triangles.push_back(t);
  }
}

}  // namespace cortex::mesh_file_detail
