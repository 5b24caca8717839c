// Copies on the vertices ride the lipid through remeshing (copy_carrier.hpp): a density
// uniform per unit area stays uniform (Poisson per cell), a coat keeps its edge, and a
// single edit moves the expected share of copies.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

#include "mesh/copy_carrier.hpp"
#include "mesh/implicit_shapes.hpp"
#include "mesh/marching_tetrahedra.hpp"
#include "mesh/remesh.hpp"
#include "copy_statistics.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

RemeshSettings sizing(double flat) {
  RemeshSettings s;
  s.sizing.flat_size = flat;
  s.sizing.min_size = flat / 4;
  s.sizing.max_size = 4 * flat;
  s.sizing.tolerance = 100.0;  // flat targets everywhere: the edge length is set by `flat`
  return s;
}


void expectUniformAfterRemeshing(SurfaceMesh m, const RemeshSettings& settings, const char* what) {
  SCOPED_TRACE(what);
  const long total = 200L * m.numVertices();
  std::vector<int> copies = testing::dropCopiesByArea(m, total, static_cast<unsigned>(m.numVertices()));
  std::vector<char> fixed(m.numVertices());
  for (Index v = 0; v < m.numVertices(); ++v) fixed[v] = m.isBoundaryVertex(v);
  VertexPayload payload{&fixed, {&copies}, {}};
  ASSERT_NEAR(testing::chiSquarePerCell(m, copies), 1.0, 0.15);
  const RemeshStats stats = remesh(m, payload, settings);
  EXPECT_GT(stats.splits + stats.collapses + stats.flips, m.numVertices() / 2) << "the pass must edit a lot";
  EXPECT_EQ(std::accumulate(copies.begin(), copies.end(), 0L), total);
  const double chi2 = testing::chiSquarePerCell(m, copies);
  std::printf("[ measured ] %s: %ld splits %ld collapses %ld flips %ld relocations, %d cells, chi2/cell %.3f\n", what,
              static_cast<long>(stats.splits), static_cast<long>(stats.collapses), static_cast<long>(stats.flips),
              static_cast<long>(stats.relocations), static_cast<int>(m.numVertices()), chi2);
  EXPECT_NEAR(chi2, 1.0, 0.2);
}

// Copies spread by area, 200 per cell on average, then one remeshing pass that edits most
// of the mesh: the density stays Poisson per cell (chi-square per cell within 0.2 of 1:
// 3.5 standard deviations, sqrt(2/cells), at the smallest mesh, ~640 cells), totals exact. On
// an icosphere and a patch refined to half their edge length and coarsened back, on a
// raw marching-tetrahedra sphere (slivers of 0.005 degrees) and on a 1:1:3 ellipsoid
// meshed by curvature. The rule this replaces (a split's new vertex took a quarter of
// each end's copies, a collapse's copies went to the merged vertex) read 4.7-133 per cell.
TEST(CopyCarrier, UniformCopiesStayUniformThroughRemeshing) {
  const SurfaceMesh sphere = testing::sphereMesh(300.0, 3), fine_sphere = testing::sphereMesh(300.0, 4);
  const SurfaceMesh patch = testing::patchMesh(600.0, 40.0), fine_patch = testing::patchMesh(1200.0, 20.0);
  expectUniformAfterRemeshing(sphere, sizing(22.0), "icosphere refined");
  expectUniformAfterRemeshing(fine_sphere, sizing(45.0), "icosphere coarsened");
  expectUniformAfterRemeshing(patch, sizing(20.0), "patch refined");
  expectUniformAfterRemeshing(fine_patch, sizing(40.0), "patch coarsened");
  const SurfaceMesh raw =
      SurfaceMesh::fromSoup(marchingTetrahedra(implicitSphere(Vec3(0, 0, 0), 600.0), 60.0), "raw mt");
  expectUniformAfterRemeshing(raw, sizing(40.0), "raw marching-tetrahedra sphere");
  const SurfaceMesh ellipsoid = SurfaceMesh::fromSoup(
      meshImplicitSurface(implicitEllipsoid(Vec3(0, 0, 0), Vec3(300, 300, 900)), 40.0), "ellipsoid");
  RemeshSettings adaptive = sizing(60.0);
  adaptive.sizing.tolerance = 0.5;
  adaptive.sizing.min_size = 8.0;
  expectUniformAfterRemeshing(ellipsoid, adaptive, "ellipsoid by curvature");
}

// A coat on the upper half of a sphere, refined: the copies stay where the lipid was.
// None is found more than two coarse edges below the coat's edge, and above two edges
// from it the coat is as uniform as it was (chi-square per cell within 0.2 of 1).
TEST(CopyCarrier, ACoatKeepsItsEdgeThroughRemeshing) {
  const double radius = 300.0, edge = 45.0;
  SurfaceMesh m = testing::sphereMesh(radius, 3);
  const long total = 200L * m.numVertices() / 2;
  std::vector<int> copies = testing::dropCopiesByArea(m, total, 8, [](const Vec3& x) { return x.z() > 0.0; });
  VertexPayload payload{nullptr, {&copies}, {}};
  remesh(m, payload, sizing(edge / 2));
  remesh(m, payload, sizing(edge / 2));
  EXPECT_EQ(std::accumulate(copies.begin(), copies.end(), 0L), total);
  long strays = 0;
  for (Index v = 0; v < m.numVertices(); ++v)
    if (m.positions()[v].z() < -2 * edge) strays += copies[v];
  EXPECT_EQ(strays, 0);
  const auto inside = [&](const Vec3& x) { return x.z() > 2 * edge; };
  EXPECT_NEAR(testing::chiSquarePerCell(m, copies, inside), 1.0, 0.2);
}

// Edits by hand on a patch's cells (the carrier trusts the triangles it is told of):
// triangle (0, 1, 2) of area 3s, s = 0.4 |C_0|, becomes (1, 2, 3): cell 0 shrinks by s,
// cell 3 grows by s, cells 1 and 2 keep their area. Each of cell 0's 100,000 copies
// leaves with probability 0.4, all for cell 3: 40,000 expected, the binomial's standard
// deviation 155, the test's window 5 of them. Then cell 3 gives all its area to cell 4:
// it is gone and all its copies go where the area went. The draws repeat for the same key.
TEST(CopyCarrier, AnEditMovesTheLipidsShareOfCopies) {
  const SurfaceMesh m = testing::patchMesh(200.0, 50.0);
  const double cell0 = dualCellAreas(m)[0];
  auto run = [&](std::uint64_t key) {
    std::vector<int> copies(m.numVertices(), 0), other(m.numVertices(), 0);
    copies[0] = 100000, other[0] = 3, other[1] = 9;
    CopyCarrier carrier({&copies, &other}, RandomStream(key, StreamId::kCopyTransport));
    carrier.measure(m);
    const double s = 0.4 * cell0;
    const FaceArea before[] = {{{0, 1, 2}, 3 * s}}, after[] = {{{1, 2, 3}, 3 * s}};
    carrier.replaced(before, after);
    EXPECT_EQ(copies[0] + copies[3], 100000);
    EXPECT_EQ(other[1], 9) << "a cell whose area did not change keeps its copies";
    EXPECT_NEAR(copies[3], 40000, 5 * 155);
    const std::vector<int> moved = copies;
    const double cell3 = dualCellAreas(m)[3] + s;  // all of it goes
    const FaceArea gone[] = {{{1, 2, 3}, 3 * cell3}}, appeared[] = {{{1, 2, 4}, 3 * cell3}};
    carrier.replaced(gone, appeared);
    EXPECT_EQ(copies[3], 0);
    EXPECT_EQ(copies[4], moved[3]);
    EXPECT_EQ(other[3], 0);
    EXPECT_EQ(other[4], 3 - other[0]);
    return std::pair{moved, copies};
  };
  EXPECT_EQ(run(11), run(11));
  EXPECT_NE(run(11).first, run(12).first);
}

}  // namespace
}  // namespace cortex
