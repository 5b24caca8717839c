// Mesh generators (icosphere, marching tetrahedra, planar patch) against closed forms and
// topological invariants, and the OBJ/PLY readers on hand-written files.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/implicit_shapes.hpp"
#include "mesh/marching_tetrahedra.hpp"
#include "mesh/mesh_file.hpp"
#include "mesh/planar_patch.hpp"

namespace cortex {
namespace {

using constants::kPi;

struct EdgeCheck {
  bool each_directed_edge_once = true;
  bool each_edge_has_twin = true;  // false on boundary edges
  long long edges = 0;             // undirected
};

EdgeCheck checkEdges(const TriangleSoup& soup) {
  std::map<std::pair<Index, Index>, int> directed;
  for (const Tri& t : soup.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  EdgeCheck check;
  for (const auto& [edge, count] : directed) {
    check.each_directed_edge_once = check.each_directed_edge_once && count == 1;
    const bool twin = directed.count({edge.second, edge.first}) > 0;
    check.each_edge_has_twin = check.each_edge_has_twin && twin;
    check.edges += twin ? (edge.first < edge.second ? 1 : 0) : 1;
  }
  return check;
}

long long eulerCharacteristic(const TriangleSoup& soup) {
  return static_cast<long long>(soup.positions.size()) - checkEdges(soup).edges +
         static_cast<long long>(soup.triangles.size());
}

Vec3 corner(const TriangleSoup& s, const Tri& t, int k) { return s.positions[t[k]]; }

double signedVolume(const TriangleSoup& s) {
  double v = 0.0;
  for (const Tri& t : s.triangles) v += corner(s, t, 0).dot(corner(s, t, 1).cross(corner(s, t, 2)));
  return v / 6.0;
}

Vec3 areaVector(const TriangleSoup& s, const Tri& t) {
  return 0.5 * (corner(s, t, 1) - corner(s, t, 0)).cross(corner(s, t, 2) - corner(s, t, 0));
}

double minAngleDegrees(const TriangleSoup& s) {
  double smallest = 180.0;
  for (const Tri& t : s.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = corner(s, t, (k + 1) % 3) - corner(s, t, k);
      const Vec3 w = corner(s, t, (k + 2) % 3) - corner(s, t, k);
      smallest = std::min(smallest, std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / kPi);
    }
  }
  return smallest;
}

double meanEdge(const TriangleSoup& s) {
  double sum = 0.0;
  for (const Tri& t : s.triangles) {
    for (int k = 0; k < 3; ++k) sum += (corner(s, t, (k + 1) % 3) - corner(s, t, k)).norm();
  }
  return sum / (3.0 * s.triangles.size());
}

void expectClosedGenusZero(const TriangleSoup& soup) {
  const EdgeCheck check = checkEdges(soup);
  EXPECT_TRUE(check.each_directed_edge_once);
  EXPECT_TRUE(check.each_edge_has_twin);
  EXPECT_EQ(eulerCharacteristic(soup), 2);
}

// Expects an InputError whose message contains `fragment` (file name, line).
template <class F>
void expectInputError(F&& f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no InputError; expected one mentioning " << fragment;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Icosphere, VertexCountsRadiusAndOrientation) {
  const Vec3 center(10.0, -20.0, 30.0);
  const double radius = 250.0;
  const int expected_vertices[] = {12, 42, 162, 642, 2562, 10242};
  for (int level = 0; level <= 5; ++level) {
    const TriangleSoup s = icosphere(center, radius, level);
    EXPECT_EQ(int(s.positions.size()), expected_vertices[level]);
    for (const Vec3& p : s.positions) EXPECT_NEAR((p - center).norm(), radius, 1e-12 * radius);
    expectClosedGenusZero(s);
    for (const Tri& t : s.triangles) {
      EXPECT_GT(areaVector(s, t).dot(corner(s, t, 0) - center), 0.0);  // outward
    }
  }
  EXPECT_THROW(icosphere(center, radius, -1), InputError);
}

TEST(Icosphere, SubdivisionsForTargetEdge) {
  const double radius = 1000.0;
  for (double target : {2000.0, 600.0, 300.0, 100.0, 50.0, 20.0}) {
    const int level = icosphereSubdivisionsFor(radius, target);
    EXPECT_LE(meanEdge(icosphere(Vec3::Zero(), radius, level)), target);
    if (level > 0) {
      EXPECT_GT(meanEdge(icosphere(Vec3::Zero(), radius, level - 1)), target);
    }
  }
  EXPECT_EQ(icosphereSubdivisionsFor(radius, 1e-3), 7);
}

// Grid nodes at x = -1000 + 50 k lie exactly on the sphere (e.g. (±1000, 0, 0)): without
// the nudge these give zero-area triangles and coincident vertices.
TEST(MarchingTetrahedra, RawSphereWithNodesOnTheSurface) {
  const double radius = 1000.0, spacing = 50.0;
  const TriangleSoup s = marchingTetrahedra(implicitSphere(Vec3::Zero(), radius), spacing);
  expectClosedGenusZero(s);
  for (const Tri& t : s.triangles) EXPECT_GT(areaVector(s, t).norm(), 0.0);
  std::vector<Vec3> sorted = s.positions;
  std::sort(sorted.begin(), sorted.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  const double exact = 4.0 / 3.0 * kPi * std::pow(radius, 3);
  EXPECT_NEAR(signedVolume(s) / exact, 1.0, 0.01);
}

TEST(MeshImplicitSurface, Sphere) {
  const double radius = 1000.0, target = 50.0;
  const Vec3 center(1500.0, 1500.0, 1500.0);
  const TriangleSoup s = meshImplicitSurface(implicitSphere(center, radius), target);
  expectClosedGenusZero(s);
  const double volume = signedVolume(s), exact = 4.0 / 3.0 * kPi * std::pow(radius, 3);
  EXPECT_GT(volume, 0.0);
  EXPECT_NEAR(volume / exact, 1.0, 0.01);
  for (const Vec3& p : s.positions) EXPECT_NEAR((p - center).norm(), radius, 1e-6 * radius);
  // Measured: min angle 22.3 deg (21.7 at edge 20), mean edge 0.998 x target. Bounds keep
  // a margin of ~7 degrees and 10%.
  const double min_angle = minAngleDegrees(s), edge_ratio = meanEdge(s) / target;
  std::cout << "[ measured ] sphere: " << s.positions.size() << " vertices, min angle "
            << min_angle << " deg, mean edge / target " << edge_ratio << '\n';
  EXPECT_GT(min_angle, 15.0);
  EXPECT_NEAR(edge_ratio, 1.0, 0.1);
}

TEST(MeshImplicitSurface, Ellipsoid) {
  const Vec3 center(1500.0, 1500.0, 1500.0), radii(1000.0, 600.0, 400.0);
  const double target = 50.0;
  const ImplicitSurface shape = implicitEllipsoid(center, radii);
  const TriangleSoup s = meshImplicitSurface(shape, target);
  expectClosedGenusZero(s);
  const double exact = 4.0 / 3.0 * kPi * radii.prod();
  EXPECT_NEAR(signedVolume(s) / exact, 1.0, 0.015);
  // The function is scaled to about the distance (min radius), so this bounds the distance.
  for (const Vec3& p : s.positions) EXPECT_LT(std::abs(shape.value(p)), 1e-6 * radii.minCoeff());
  // Measured: min angle 24.4 deg, mean edge 0.997 x target.
  const double min_angle = minAngleDegrees(s), edge_ratio = meanEdge(s) / target;
  std::cout << "[ measured ] ellipsoid: " << s.positions.size() << " vertices, min angle "
            << min_angle << " deg, mean edge / target " << edge_ratio << '\n';
  EXPECT_GT(min_angle, 15.0);
  EXPECT_NEAR(edge_ratio, 1.0, 0.1);
}

// A user-defined function without analytic gradient, and of genus 1.
TEST(MeshImplicitSurface, TorusFromPlainFunction) {
  const double big = 800.0, small = 300.0;
  ImplicitSurface torus;
  torus.value = [=](const Vec3& x) {
    return std::hypot(std::hypot(x.x(), x.y()) - big, x.z()) - small;
  };
  torus.box_min = -Vec3(big + small, big + small, small);
  torus.box_max = -torus.box_min;
  const TriangleSoup s = meshImplicitSurface(torus, 50.0);
  const EdgeCheck check = checkEdges(s);
  EXPECT_TRUE(check.each_directed_edge_once && check.each_edge_has_twin);
  EXPECT_EQ(eulerCharacteristic(s), 0);
  EXPECT_NEAR(signedVolume(s) / (2.0 * kPi * kPi * big * small * small), 1.0, 0.015);
  EXPECT_GT(minAngleDegrees(s), 15.0);
}

// Rim curvature radius 3.6 nm: an edge of 50 joins the two sheets and folds the mesh.
TEST(MeshImplicitSurface, RefusesShapesThinnerThanTheEdge) {
  const ImplicitSurface disc = implicitEllipsoid(Vec3::Zero(), Vec3(1000.0, 1000.0, 60.0));
  expectInputError([&] { meshImplicitSurface(disc, 50.0); }, "too coarse");
  expectInputError([] { meshImplicitSurface(implicitSphere(Vec3::Zero(), 100.0), 500.0); },
                   "too coarse");
}

TEST(ImplicitSurface, NumericalGradientMatchesAnalytic) {
  ImplicitSurface shape = implicitEllipsoid(Vec3(1.0, 2.0, 3.0), Vec3(300.0, 200.0, 100.0));
  const Vec3 x(150.0, -40.0, 70.0);
  const Vec3 analytic = shape.gradientAt(x);
  shape.gradient = nullptr;
  EXPECT_LT((shape.gradientAt(x) - analytic).norm(), 1e-6 * analytic.norm());
}

TEST(PlanarPatch, ExactRectangleFacingPlusZ) {
  const Vec3 center(100.0, -50.0, 7.0);
  const double lx = 1000.0, ly = 600.0, target = 50.0;
  const TriangleSoup s = planarPatch(center, lx, ly, target);
  double area = 0.0;
  for (const Tri& t : s.triangles) {
    const Vec3 a = areaVector(s, t);
    EXPECT_GT(a.z(), 0.0);
    area += a.z();
  }
  EXPECT_NEAR(area, lx * ly, 1e-9 * lx * ly);
  for (const Vec3& p : s.positions) {
    EXPECT_EQ(p.z(), center.z());
    EXPECT_LE(std::abs(p.x() - center.x()), lx / 2.0 + 1e-9 * lx);
    EXPECT_LE(std::abs(p.y() - center.y()), ly / 2.0 + 1e-9 * ly);
  }
  const EdgeCheck check = checkEdges(s);
  EXPECT_TRUE(check.each_directed_edge_once);
  EXPECT_EQ(eulerCharacteristic(s), 1);  // a disc
  // Measured 30.3 deg: interior triangles are near-equilateral, the half triangles on the
  // sides have ~30 deg.
  const double min_angle = minAngleDegrees(s);
  std::cout << "[ measured ] planar patch: min angle " << min_angle << " deg, mean edge / target "
            << meanEdge(s) / target << '\n';
  EXPECT_GT(min_angle, 29.0);
}

// ---- files ----

std::filesystem::path scratchFile(const std::string& name) {
  return std::filesystem::path(::testing::TempDir()) / ("cortex_mesh_" + name);
}

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(MeshFile, ObjRoundTripIsExact) {
  const TriangleSoup original = icosphere(Vec3(0.1, 0.2, 0.3), 1.0 / 3.0, 2);
  const auto path = scratchFile("roundtrip.obj");
  writeObj(path, original);
  const TriangleSoup read = readMeshFile(path);
  EXPECT_EQ(read.positions, original.positions);
  EXPECT_EQ(read.triangles, original.triangles);
}

TEST(MeshFile, ObjFeatures) {
  const auto path = scratchFile("features.obj");
  writeText(path,
            "# a square and a triangle\nmtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            "v 9 9 9\r\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3//1 4\nv 2 0 0\nf -5 -1 -4 # relative\n");
  const TriangleSoup s = readMeshFile(path);
  ASSERT_EQ(s.positions.size(), 5u);  // (9, 9, 9) is unused and dropped
  EXPECT_EQ(s.positions[4], Vec3(2, 0, 0));
  const std::vector<Tri> expected = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}};
  EXPECT_EQ(s.triangles, expected);
}

TEST(MeshFile, AsciiPlyWithExtraProperties) {
  const auto path = scratchFile("ascii.ply");
  writeText(path,
            "ply\nformat ascii 1.0\ncomment by hand\nelement vertex 4\nproperty double x\n"
            "property float nx\nproperty double y\nproperty double z\nproperty uchar red\n"
            "element face 1\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
            "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
            "0 9 0 0 255\n1 9 0 0 0\n1 9 1 0 0\n0 9 1 0 0\n7 4 0 1 2 3\n0 1\n");
  const TriangleSoup s = readMeshFile(path);
  ASSERT_EQ(s.positions.size(), 4u);
  EXPECT_EQ(s.positions[2], Vec3(1, 1, 0));
  const std::vector<Tri> expected = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_EQ(s.triangles, expected);
}

TEST(MeshFile, BinaryLittleEndianPly) {
  const auto path = scratchFile("binary.ply");
  std::string bytes =
      "ply\r\nformat binary_little_endian 1.0\r\nelement vertex 3\r\nproperty float x\r\n"
      "property float y\r\nproperty float z\r\nproperty short tag\r\nelement face 1\r\n"
      "property list uchar uint vertex_index\r\nend_header\r\n";
  auto append = [&bytes](const auto& value) {  // test machines are little-endian
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
  };
  const float coords[3][3] = {{0.5f, 0, 0}, {0, -1.25f, 0}, {0, 0, 2}};
  for (const auto& c : coords) {
    for (float x : c) append(x);
    append(std::int16_t(-7));
  }
  append(std::uint8_t(3));
  for (std::uint32_t v : {0u, 1u, 2u}) append(v);
  writeText(path, bytes);
  const TriangleSoup s = readMeshFile(path);
  ASSERT_EQ(s.positions.size(), 3u);
  EXPECT_EQ(s.positions[1], Vec3(0, -1.25, 0));
  EXPECT_EQ(s.triangles, std::vector<Tri>({{0, 1, 2}}));

  writeText(path, bytes.substr(0, bytes.size() - 2));  // truncated inside the face
  expectInputError([&] { readMeshFile(path); }, "binary.ply: face 0: file ends early");
}

TEST(MeshFile, ErrorsNameTheFileAndLine) {
  const auto bad_index = scratchFile("bad_index.obj");
  writeText(bad_index, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  expectInputError([&] { readMeshFile(bad_index); }, "bad_index.obj:4: vertex index");

  const auto not_number = scratchFile("not_number.obj");
  writeText(not_number, "v 0 0 0\nv 1 zero 0\n");
  expectInputError([&] { readMeshFile(not_number); }, "not_number.obj:2:");

  const auto missing = scratchFile("missing_coordinate.ply");
  writeText(missing, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n");
  expectInputError([&] { readMeshFile(missing); }, "missing_coordinate.ply");

  const auto big_endian = scratchFile("big.ply");
  writeText(big_endian, "ply\nformat binary_big_endian 1.0\nend_header\n");
  expectInputError([&] { readMeshFile(big_endian); }, "big.ply:2: unsupported");

  const auto no_faces = scratchFile("points.obj");
  writeText(no_faces, "v 0 0 0\n");
  expectInputError([&] { readMeshFile(no_faces); }, "points.obj: no triangles");

  expectInputError([] { readMeshFile(scratchFile("does_not_exist.obj")); }, "does_not_exist.obj");
  expectInputError([] { readMeshFile(scratchFile("mesh.stl")); }, "mesh.stl");
}

}  // namespace
}  // namespace cortex
