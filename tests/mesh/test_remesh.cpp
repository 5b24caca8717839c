// Adaptive remeshing: quality, shape preservation, curvature adaptivity, robustness and
// conservation of per-vertex data.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "core/constants.hpp"
#include "mesh/geometry.hpp"
#include "mesh/implicit_shapes.hpp"
#include "mesh/marching_tetrahedra.hpp"
#include "mesh/mesh_quality.hpp"
#include "mesh/remesh.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

double volumeOf(const SurfaceMesh& m) {
  MeshGeometry g;
  g.compute(MeshTopology::of(m), testing::flatPositions(m).data());
  return g.volume;
}

MeshQuality qualityOf(const SurfaceMesh& m) { return measureQuality(MeshTopology::of(m), m.positions()); }

RemeshSettings settingsFor(double flat, double tolerance) {
  RemeshSettings s;
  s.sizing.flat_size = flat;
  s.sizing.min_size = flat / 4;
  s.sizing.max_size = 2 * flat;
  s.sizing.tolerance = tolerance;
  return s;
}

// Issue acceptance: one pass on a raw marching-tetrahedra sphere (minimum angle ~0°)
// raises the minimum angle above 25° and keeps the volume within 0.5%.
TEST(Remesh, OnePassRepairsARawMarchingTetrahedraSphere) {
  const double R = 1000.0;
  SurfaceMesh m = SurfaceMesh::fromSoup(marchingTetrahedra(implicitSphere(Vec3(0, 0, 0), R), 95.0), "raw mt");
  const double v0 = volumeOf(m);
  ASSERT_LT(qualityOf(m).min_angle_deg, 5.0) << "the raw mesh should be bad for this test to mean anything";
  VertexPayload none;
  const RemeshStats stats = remesh(m, none, settingsFor(50.0, 50.0 * 50.0 / (6 * R)));
  EXPECT_NO_THROW(m.validate());
  const MeshQuality q = qualityOf(m);
  std::printf("[ measured ] min angle %.2f deg, volume change %.3g, %d splits %d collapses %d flips, %d sweeps\n",
              q.min_angle_deg, volumeOf(m) / v0 - 1, stats.splits, stats.collapses, stats.flips, stats.sweeps);
  EXPECT_GT(q.min_angle_deg, 25.0);
  EXPECT_NEAR(volumeOf(m) / v0, 1.0, 0.005);
  EXPECT_EQ(m.eulerCharacteristic(), 2);
}

}  // namespace
}  // namespace cortex
