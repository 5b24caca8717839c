// Reading PLY: the header, then the data section as ASCII lines or little-endian binary
// records. Only vertex x, y, z and face index lists are kept; other elements and
// properties are read only to be skipped.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "mesh/mesh_file_parsing.hpp"

namespace cortex::mesh_file_detail {
namespace {

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

}  // namespace

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

}  // namespace cortex::mesh_file_detail
