// Reading Wavefront OBJ: only 'v' and 'f' lines matter; other statements are skipped.
#include <charconv>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "mesh/mesh_file_parsing.hpp"

namespace cortex::mesh_file_detail {

TriangleSoup readObj(const Path& path) {
  const std::string text = readAll(path);
  TriangleSoup soup;
  // Faces may name vertices defined later, so indices are checked once all are read.
  std::vector<std::pair<std::vector<long long>, int>> faces;
  int line_no = 0;
  for (std::string_view line : splitLines(text)) {
    ++line_no;
    const std::vector<std::string_view> w = splitWords(line.substr(0, line.find('#')));
    if (w.empty()) continue;
    const std::string where = std::to_string(line_no);
    if (w[0] == "v") {
      if (w.size() < 4) fail(path, where, "vertex needs 3 coordinates");
      Vec3 p;
      for (int k = 0; k < 3; ++k) {
        const std::optional<double> x = parseNumber(w[k + 1]);
        if (!x) fail(path, where, fmt::format("'{}' is not a finite number", w[k + 1]));
        p[k] = *x;
      }
      soup.positions.push_back(p);
    } else if (w[0] == "f") {
      std::vector<long long> polygon;
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::string_view ref = w[k].substr(0, w[k].find('/'));  // drop /vt/vn
        long long v = 0;
        const auto [end, error] = std::from_chars(ref.data(), ref.data() + ref.size(), v);
        if (error != std::errc() || end != ref.data() + ref.size() || v == 0) {
          fail(path, where, fmt::format("bad vertex reference '{}'", w[k]));
        }
        // Negative indices count back from the last vertex read so far.
        polygon.push_back(v > 0 ? v - 1 : static_cast<long long>(soup.positions.size()) + v);
      }
      faces.emplace_back(std::move(polygon), line_no);
    }
  }
  for (const auto& [polygon, line] : faces) {
    addPolygon(soup, polygon, soup.positions.size(), path, std::to_string(line));
  }
  return soup;
}

}  // namespace cortex::mesh_file_detail
