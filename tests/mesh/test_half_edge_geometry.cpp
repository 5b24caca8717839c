// Half-edge connectivity invariants and discrete geometry against exact results.
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "mesh/cotan.hpp"
#include "mesh/geometry.hpp"
#include "mesh/implicit_shapes.hpp"
#include "mesh/marching_tetrahedra.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

using constants::kPi;

MeshGeometry geometryOf(const SurfaceMesh& m) {
  MeshGeometry g;
  g.compute(MeshTopology::of(m), flatCoordinates(m.positions()).data());
  return g;
}

// Sum over vertices of the angle defect 2*pi - sum of corner angles (pi - ... on a boundary).
double totalAngleDefect(const SurfaceMesh& m) {
  std::vector<double> angle_sum(m.numVertices(), 0.0);
  for (const Tri& t : m.triangles())
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = m.positions()[t[k]];
      const Vec3 u = m.positions()[t[(k + 1) % 3]] - p, v = m.positions()[t[(k + 2) % 3]] - p;
      angle_sum[t[k]] += std::atan2(u.cross(v).norm(), u.dot(v));
    }
  double defect = 0.0;
  for (Index v = 0; v < m.numVertices(); ++v) defect += (m.isBoundaryVertex(v) ? kPi : 2 * kPi) - angle_sum[v];
  return defect;
}

TEST(HalfEdgeMesh, ClosedSphereIsValidGenusZero) {
  for (int level = 0; level <= 3; ++level) {
    const SurfaceMesh m = testing::sphereMesh(1.0, level);
    EXPECT_NO_THROW(m.validate());
    EXPECT_TRUE(m.isClosed());
    EXPECT_EQ(m.eulerCharacteristic(), 2);
    for (Index v = 0; v < m.numVertices(); ++v) EXPECT_EQ(m.valence(v), level == 0 || v < 12 ? 5 : 6);
  }
}

TEST(HalfEdgeMesh, PatchHasOneBoundaryLoopAndEulerCharacteristicOne) {
  const SurfaceMesh m = testing::patchMesh(200.0, 20.0);
  EXPECT_NO_THROW(m.validate());
  EXPECT_FALSE(m.isClosed());
  EXPECT_EQ(m.eulerCharacteristic(), 1);
  Index boundary_halfedges = 0;
  for (Index h = 0; h < m.numHalfedges(); ++h) boundary_halfedges += m.isBoundaryHalfedge(h);
  Index h = m.numHalfedges() - 1, loop = 0;
  while (!m.isBoundaryHalfedge(h)) --h;
  const Index start = h;
  do {
    h = m.next(h);
    ++loop;
  } while (h != start);
  EXPECT_EQ(loop, boundary_halfedges) << "the boundary must be a single loop";
}

// Gauss-Bonnet: total angle defect is 2*pi*chi on a closed mesh, exactly up to round-off.
TEST(HalfEdgeMesh, GaussBonnetHoldsOnClosedMeshes) {
  EXPECT_NEAR(totalAngleDefect(testing::sphereMesh(3.0, 3, 0.2)), 4 * kPi, 1e-10);
  const SurfaceMesh mt = SurfaceMesh::fromSoup(
      meshImplicitSurface(implicitEllipsoid(Vec3(1, 2, 3), Vec3(300, 200, 120)), 25.0), "ellipsoid");
  EXPECT_EQ(mt.eulerCharacteristic(), 2);
  EXPECT_NEAR(totalAngleDefect(mt), 4 * kPi, 1e-10);
}

TEST(HalfEdgeMesh, RejectsBrokenSoupsNamingTheSource) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {-1, -1, 2}};
  auto expectError = [&](std::vector<Tri> tris, const char* what) {
    try {
      SurfaceMesh::fromSoup({p, std::move(tris)}, "bad.obj");
      ADD_FAILURE() << "accepted a mesh with " << what;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.obj"), std::string::npos) << e.what();
    }
  };
  expectError({{0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {3, 4, 5}, {2, 5, 3}}, "an edge in three triangles");
  expectError({{0, 1, 2}, {0, 1, 3}, {2, 3, 4}, {4, 5, 0}, {1, 5, 4}}, "inconsistent orientation");
  expectError({{0, 1, 2}, {0, 2, 1}, {3, 4, 5}}, "two triangles on the same vertices");
  expectError({{0, 1, 7}, {3, 4, 5}}, "an out-of-range index");
  // Two triangles touching at vertex 0 only (a bow tie) plus an unused vertex.
  expectError({{0, 1, 2}, {0, 3, 4}}, "a non-manifold vertex or an unused vertex");
  const std::vector<Vec3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_THROW(SurfaceMesh::fromSoup({line, {{0, 1, 2}}}, "flat.obj"), InputError);
}

// Area and volume of projected icospheres converge to 4 pi R^2 and 4/3 pi R^3 at second
// order in the edge length: the error falls about 4x per subdivision.
TEST(Geometry, SphereAreaAndVolumeConvergeAtSecondOrder) {
  const double R = 500.0;
  double previous_area_error = 0, previous_volume_error = 0;
  for (int level = 2; level <= 5; ++level) {
    const MeshGeometry g = geometryOf(testing::sphereMesh(R, level, 0.0, Vec3(1500, 1500, 1500)));
    const double area_error = 1.0 - g.area / (4 * kPi * R * R);
    const double volume_error = 1.0 - g.volume / (4.0 / 3.0 * kPi * R * R * R);
    EXPECT_GT(area_error, 0.0);  // inscribed polyhedron
    EXPECT_GT(volume_error, 0.0);
    if (level > 2) {
      EXPECT_NEAR(previous_area_error / area_error, 4.0, 0.3);
      EXPECT_NEAR(previous_volume_error / volume_error, 4.0, 0.3);
    }
    previous_area_error = area_error;
    previous_volume_error = volume_error;
  }
  EXPECT_LT(previous_area_error, 1e-3);
  EXPECT_LT(previous_volume_error, 1e-3);
}

TEST(Geometry, VertexAreasPartitionTheTotalArea) {
  const MeshGeometry g = geometryOf(testing::sphereMesh(100.0, 3, 2.0));
  double sum = 0.0;
  for (double a : g.vertex_area) sum += a;
  EXPECT_NEAR(sum, g.area, 1e-9 * g.area);
}

// dA/dx_i = sum_j w_ij (x_i - x_j): the area gradient is the cotan Laplacian of position.
TEST(Geometry, AreaGradientEqualsCotanLaplacianOfPosition) {
  const SurfaceMesh m = testing::sphereMesh(100.0, 3, 3.0);
  const MeshGeometry g = geometryOf(m);
  const std::vector<double> w = cotanWeights(m);
  for (Index v = 0; v < m.numVertices(); ++v) {
    Vec3 lap = Vec3::Zero();
    Index h = m.outgoing(v);
    do {
      lap += w[h] * (m.positions()[v] - m.positions()[m.tip(h)]);
      h = m.rotate(h);
    } while (h != m.outgoing(v));
    EXPECT_LT((lap - g.area_gradient[v]).norm(), 1e-10 * g.area_gradient[v].norm());
  }
}

// The constraint check's shortcut sums exactly what compute sums: a shape that holds its
// area and volume by one holds them by the other, to the last bit (sphereMesh's third
// argument perturbs the vertices, so no symmetry hides a difference).
TEST(Geometry, AreaAndVolumeAloneEqualTheFullComputationBitForBit) {
  for (const double jitter : {0.0, 2.0, 5.0}) {
    const SurfaceMesh m = testing::sphereMesh(100.0, 3, jitter, Vec3(300, -200, 50));
    const MeshGeometry g = geometryOf(m);
    const MeshTopology topology = MeshTopology::of(m);
    EXPECT_EQ(totalArea(topology, flatCoordinates(m.positions()).data()), g.area) << "jitter " << jitter;
    EXPECT_EQ(signedVolume(topology, flatCoordinates(m.positions()).data()), g.volume) << "jitter " << jitter;
  }
}

TEST(Geometry, VolumeIsIndependentOfTranslation) {
  const MeshGeometry a = geometryOf(testing::sphereMesh(100.0, 3, 2.0));
  const MeshGeometry b = geometryOf(testing::sphereMesh(100.0, 3, 2.0, Vec3(1e4, -2e4, 3e4)));
  EXPECT_NEAR(a.volume, b.volume, 1e-9 * a.volume);
}

}  // namespace
}  // namespace cortex
