// Triangle meshes from and to files: a membrane can start from any closed surface.
#pragma once

#include <filesystem>

#include "mesh/triangle_soup.hpp"

namespace cortex {

// Reads .obj (v/f lines, 'a/b/c' parts, negative relative indices) or .ply (ASCII or
// binary little-endian; x, y, z of any numeric type and a 'vertex_indices'/'vertex_index'
// list), chosen by extension. Polygons are fan-triangulated and vertices no face uses are
// dropped. Manifoldness is not checked here (the half-edge builder does that).
// Throws InputError "file:line: problem" (binary PLY: "file: face 12: problem").
TriangleSoup readMeshFile(const std::filesystem::path& path);

// Writes v/f lines with round-trip exact coordinates. Throws InputError if it cannot.
void writeObj(const std::filesystem::path& path, const TriangleSoup& soup);

}  // namespace cortex
