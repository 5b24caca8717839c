#include "mesh/mesh_file.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "core/error.hpp"

namespace cortex {
namespace {

using Path = std::filesystem::path;

// "file:where: problem"; `where` is a line number, " face 12" (binary PLY) or empty.
[[noreturn]] void fail(const Path& path, const std::string& where, const std::string& problem) {
  const char* separator = where.empty() ? "" : ":";
  throw InputError(fmt::format("{}{}{}: {}", path.string(), separator, where, problem));
}

std::string readAll(const Path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open mesh file", path.string()));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Lines without their '\n' or '\r\n' ending.
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

// Collects polygons as triangle fans, checking indices against the vertex count.
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

// ---- PLY ----

struct PlyType {
  int bytes = 0;
  bool is_float = false, is_signed = false;
};

std::optional<PlyType> plyType(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType{1, false, true};
  if (name == "uchar" || name == "uint8") return PlyType{1, false, false};
  if (name == "short" || name == "int16") return PlyType{2, false, true};
  if (name == "ushort" || name == "uint16") return PlyType{2, false, false};
  if (name == "int" || name == "int32") return PlyType{4, false, true};
  if (name == "uint" || name == "uint32") return PlyType{4, false, false};
  if (name == "float" || name == "float32") return PlyType{4, true, true};
  if (name == "double" || name == "float64") return PlyType{8, true, true};
  return std::nullopt;
}

struct PlyProperty {
  std::string name;
  PlyType type;
  std::optional<PlyType> list_count;  // set for list properties
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

// Values of the data section, one record (element instance) at a time. ASCII records are
// one line each; binary ones are located by element name and number in messages.
class PlyValues {
 public:
  PlyValues(const Path& path, std::string_view data, bool binary, int first_line)
      : path_(path), data_(data), binary_(binary), line_no_(first_line - 1) {
    if (!binary) lines_ = splitLines(data);
  }

  void beginRecord(const std::string& element, long long index) {
    if (binary_) {
      where_ = fmt::format(" {} {}", element, index);
      return;
    }
    do {
      if (next_line_ >= lines_.size()) fail(path_, "", fmt::format("file ends in '{}'", element));
      words_ = splitWords(lines_[next_line_++]);
      ++line_no_;
    } while (words_.empty());
    next_word_ = 0;
    where_ = std::to_string(line_no_);
  }

  void endRecord() const {
    if (!binary_ && next_word_ != words_.size()) fail(path_, where_, "more values than declared");
  }

  double read(const PlyType& type) {
    if (!binary_) {
      if (next_word_ >= words_.size()) fail(path_, where_, "fewer values than declared");
      const std::string_view word = words_[next_word_++];
      const std::optional<double> value = parseNumber(word);
      if (!value) fail(path_, where_, fmt::format("'{}' is not a finite number", word));
      return *value;
    }
    if (offset_ + type.bytes > data_.size()) fail(path_, where_, "file ends early");
    std::uint64_t raw = 0;  // assembled from little-endian bytes, whatever the host order
    for (int i = type.bytes - 1; i >= 0; --i) raw = raw << 8 | std::uint8_t(data_[offset_ + i]);
    offset_ += type.bytes;
    if (type.is_float) {
      const double value = type.bytes == 4 ? double(std::bit_cast<float>(std::uint32_t(raw)))
                                           : std::bit_cast<double>(raw);
      if (!std::isfinite(value)) fail(path_, where_, "value is not a finite number");
      return value;
    }
    if (type.is_signed && (raw >> (8 * type.bytes - 1)) != 0) {  // sign-extend (ints <= 4 bytes)
      return double(std::int64_t(raw) - (std::int64_t(1) << (8 * type.bytes)));
    }
    return double(raw);
  }

  const std::string& where() const { return where_; }

 private:
  const Path& path_;
  std::string_view data_;
  bool binary_;
  std::vector<std::string_view> lines_, words_;
  std::size_t next_line_ = 0, next_word_ = 0, offset_ = 0;
  int line_no_;
  std::string where_;
};

// Counts and vertex indices are read as doubles, exact up to 2^53.
long long wholeNumber(const Path& path, const std::string& where, double v) {
  if (!(v >= 0.0 && v <= 0x1p53) || v != std::floor(v)) {
    fail(path, where, fmt::format("bad count or index {}", v));
  }
  return static_cast<long long>(v);
}

struct PlyHeader {
  std::vector<PlyElement> elements;
  bool binary = false;
  std::size_t data_offset = 0;  // first byte after "end_header\n"
  int line_count = 0;
};

PlyHeader readPlyHeader(const Path& path, const std::string& text) {
  PlyHeader header;
  std::vector<PlyElement>& elements = header.elements;
  std::size_t& offset = header.data_offset;  // start of the current line until the end
  int& line_no = header.line_count;
  for (bool ended = false; !ended;) {
    const std::size_t end = text.find('\n', offset);
    if (end == std::string::npos) fail(path, std::to_string(line_no + 1), "no end_header");
    std::string_view line(text.data() + offset, end - offset);
    offset = end + 1;
    const std::string where = std::to_string(++line_no);
    const std::vector<std::string_view> w = splitWords(line);
    if (line_no == 1) {
      if (w.size() != 1 || w[0] != "ply") fail(path, where, "not a PLY file (no 'ply' magic)");
    } else if (w.empty() || w[0] == "comment" || w[0] == "obj_info") {
      continue;
    } else if (w[0] == "format") {
      if (w.size() < 2 || (w[1] != "ascii" && w[1] != "binary_little_endian")) {
        fail(path, where, "unsupported PLY format (ascii and binary_little_endian are read)");
      }
      header.binary = w[1] == "binary_little_endian";
    } else if (w[0] == "element" && w.size() == 3) {
      const std::optional<double> count = parseNumber(w[2]);
      if (!count) fail(path, where, "bad element count");
      elements.push_back({std::string(w[1]), wholeNumber(path, where, *count), {}});
    } else if (w[0] == "property" && !elements.empty()) {
      const bool list = w.size() > 1 && w[1] == "list";
      if (w.size() != (list ? 5u : 3u)) fail(path, where, "malformed property line");
      const std::optional<PlyType> type = plyType(w[list ? 3 : 1]);
      const std::optional<PlyType> count = list ? plyType(w[2]) : std::nullopt;
      if (!type || (list && !count)) fail(path, where, "unknown property type");
      elements.back().properties.push_back({std::string(w.back()), *type, count});
    } else if (w[0] == "end_header") {
      ended = true;
    } else {
      fail(path, where, fmt::format("unrecognized header line '{}'", line));
    }
  }
  return header;
}

TriangleSoup readPly(const Path& path) {
  const std::string text = readAll(path);
  const PlyHeader header = readPlyHeader(path, text);
  const std::vector<PlyElement>& elements = header.elements;
  auto vertex_it = std::find_if(elements.begin(), elements.end(),
                                [](const PlyElement& e) { return e.name == "vertex"; });
  if (vertex_it == elements.end()) fail(path, "", "no vertex element");
  for (std::string_view axis : {"x", "y", "z"}) {
    if (std::none_of(vertex_it->properties.begin(), vertex_it->properties.end(),
                     [&](const PlyProperty& p) { return p.name == axis && !p.list_count; })) {
      fail(path, "", fmt::format("vertex element lacks a scalar property {}", axis));
    }
  }
  auto is_index_list = [](const PlyProperty& p) {
    return p.list_count && (p.name == "vertex_indices" || p.name == "vertex_index");
  };
  TriangleSoup soup;
  PlyValues values(path, std::string_view(text).substr(header.data_offset), header.binary,
                   header.line_count + 1);
  for (const PlyElement& element : elements) {
    const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
    if (is_face && std::none_of(element.properties.begin(), element.properties.end(),
                                is_index_list)) {
      fail(path, "", "face element lacks a 'vertex_indices' list");
    }
    for (long long r = 0; r < element.count; ++r) {
      values.beginRecord(element.name, r);
      const std::string& where = values.where();
      Vec3 p = Vec3::Zero();
      std::vector<long long> polygon;
      for (const PlyProperty& prop : element.properties) {
        const long long n =
            prop.list_count ? wholeNumber(path, where, values.read(*prop.list_count)) : 1;
        for (long long i = 0; i < n; ++i) {
          const double v = values.read(prop.type);  // read even if unused, to skip it
          if (is_vertex && !prop.list_count && (prop.name == "x" || prop.name == "y" ||
                                                prop.name == "z")) {
            p[prop.name[0] - 'x'] = v;
          }
          if (is_face && is_index_list(prop)) polygon.push_back(wholeNumber(path, where, v));
        }
      }
      values.endRecord();
      if (is_vertex) soup.positions.push_back(p);
      if (is_face) addPolygon(soup, polygon, std::size_t(vertex_it->count), path, where);
    }
  }
  return soup;
}

// Vertices no triangle uses are dropped; the others keep their relative order.
void dropUnreferencedVertices(TriangleSoup& soup) {
  std::vector<Index> new_index(soup.positions.size(), -1);
  for (const Tri& t : soup.triangles) {
    for (Index v : t) new_index[v] = 0;
  }
  std::vector<Vec3> kept;
  for (std::size_t v = 0; v < new_index.size(); ++v) {
    if (new_index[v] < 0) continue;
    new_index[v] = Index(kept.size());
    kept.push_back(soup.positions[v]);
  }
  for (Tri& t : soup.triangles) {
    for (Index& v : t) v = new_index[v];
  }
  soup.positions = std::move(kept);
}

}  // namespace

TriangleSoup readMeshFile(const Path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  TriangleSoup soup;
  if (ext == ".obj") {
    soup = readObj(path);
  } else if (ext == ".ply") {
    soup = readPly(path);
  } else {
    throw InputError(
        fmt::format("{}: unsupported mesh format '{}' (use .obj or .ply)", path.string(), ext));
  }
  if (soup.triangles.empty()) throw InputError(fmt::format("{}: no triangles", path.string()));
  dropUnreferencedVertices(soup);
  return soup;
}

void writeObj(const Path& path, const TriangleSoup& soup) {
  std::ofstream out(path);
  char buffer[32];  // std::to_chars writes the shortest text that reads back exactly
  for (const Vec3& p : soup.positions) {
    out << 'v';
    for (int k = 0; k < 3; ++k) {
      out << ' ' << std::string_view(buffer, std::to_chars(buffer, std::end(buffer), p[k]).ptr);
    }
    out << '\n';
  }
  for (const Tri& t : soup.triangles) {
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  if (!out.flush()) throw InputError(fmt::format("{}: cannot write mesh file", path.string()));
}

}  // namespace cortex
