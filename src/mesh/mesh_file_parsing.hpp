// Internal to the mesh-file readers (mesh_file.cpp, obj_file.cpp, ply_file.cpp): the text
// helpers both formats use, so that both report problems as "file:line: problem", and the
// per-format readers that readMeshFile() dispatches to. Not for use elsewhere.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/triangle_soup.hpp"

// A namespace of their own: names as general as fail() would risk clashing in cortex.
namespace cortex::mesh_file_detail {

using Path = std::filesystem::path;

// Throws InputError "file:where: problem"; `where` is a line number, " face 12" (binary
// PLY) or empty.
[[noreturn]] void fail(const Path& path, const std::string& where, const std::string& problem);

// The whole file as bytes. Throws InputError if it cannot be opened.
std::string readAll(const Path& path);

// Lines without their '\n' or '\r\n' ending.
std::vector<std::string_view> splitLines(std::string_view text);

// Words separated by spaces, tabs and the other blanks.
std::vector<std::string_view> splitWords(std::string_view line);

// The whole word as a finite number, or nothing.
std::optional<double> parseNumber(std::string_view word);

// Appends the polygon as a triangle fan, first checking its indices against
// vertex_count; problems are reported at `where`.
void addPolygon(TriangleSoup& soup, const std::vector<long long>& polygon,
                std::size_t vertex_count, const Path& path, const std::string& where);

// The polygons of one file as written, unused vertices kept and no triangles allowed:
// the checks common to both formats are left to readMeshFile().
TriangleSoup readObj(const Path& path);
TriangleSoup readPly(const Path& path);

}  // namespace cortex::mesh_file_detail
