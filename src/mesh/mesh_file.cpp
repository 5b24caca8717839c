#include "mesh/mesh_file.hpp"

#include <cctype>
#include <charconv>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "core/error.hpp"
#include "mesh/mesh_file_parsing.hpp"
#include "mesh/soup_cleanup.hpp"

namespace cortex {

// Larger than any mesh cortex can simulate; also stops /dev/zero and the like early.
constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{4} << 30;

TriangleSoup readMeshFile(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw InputError(fmt::format("{}: no such mesh file", path.string()));
  if (!std::filesystem::is_regular_file(status))
    throw InputError(fmt::format("{}: not a regular file (a folder or a device?)", path.string()));
  if (std::filesystem::file_size(path, ec) > kMaxMeshFileBytes)
    throw InputError(fmt::format("{}: larger than 4 GiB, not a mesh cortex can use", path.string()));
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  TriangleSoup soup;
  if (ext == ".obj") {
    soup = mesh_file_detail::readObj(path);
  } else if (ext == ".ply") {
    soup = mesh_file_detail::readPly(path);
  } else {
    throw InputError(
        fmt::format("{}: unsupported mesh format '{}' (use .obj or .ply)", path.string(), ext));
  }
  if (soup.triangles.empty()) throw InputError(fmt::format("{}: no triangles", path.string()));
  dropUnreferencedVertices(soup);
  return soup;
}

void writeObj(const std::filesystem::path& path, const TriangleSoup& soup) {
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
