// Copies carried by the lipid's potential flow when a deformation changes the cells'
// areas on a fixed mesh (mesh/lipid_flow.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

#include "mesh/copy_carrier.hpp"
#include "mesh/lipid_flow.hpp"
#include "copy_statistics.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

// 200 copies per cell spread by area, then the vertices moved by `deform`: left in place
// the copies no longer match a uniform density; carried by the flow, chi-square per cell
// within 0.15 of 1 (> 3 standard deviations, sqrt(2/cells) <= 0.04 here). Totals exact.
template <class Deform>
void expectFlowKeepsUniform(SurfaceMesh m, Deform deform, const char* what) {
  SCOPED_TRACE(what);
  const long total = 200L * m.numVertices();
  std::vector<int> copies = testing::dropCopiesByArea(m, total, static_cast<unsigned>(m.numVertices()));
  const std::vector<double> before = dualCellAreas(m);
  for (Vec3& x : m.positions()) x = deform(x);
  const double left_in_place = testing::chiSquarePerCell(m, copies);
  EXPECT_GT(left_in_place, 2.0) << "the deformation must matter for the test to mean anything";
  RandomStream random(1, StreamId::kCopyTransport);
  const LipidFlowStats stats = carryWithLipidFlow(m, before, dualCellAreas(m), {&copies}, random);
  const double carried = testing::chiSquarePerCell(m, copies);
  std::printf("[ measured ] %s: chi2/cell left in place %.2f, carried %.3f (%d sub-steps, largest outflow %.2f)\n",
              what, left_in_place, carried, stats.substeps, stats.largest_outflow);
  EXPECT_EQ(std::accumulate(copies.begin(), copies.end(), 0L), total);
  EXPECT_NEAR(carried, 1.0, 0.15);
}

// A sphere (R = 300 nm, 2,562 vertices) stretched into a 1 : 1 : 1.8 spheroid (the
// equator's cells grow ~1.8-fold, the poles' keep their size); the same sphere made lumpy
// by a radial perturbation of 30% (r -> r (1 + 0.3 xy/R^2 + 0.2 z/R)); a 1200 nm patch
// (20 nm edges, open boundary) with a Gaussian bump of 300 nm height and 150 nm width
// raised in its middle.
TEST(LipidFlow, KeepsAUniformDensityUniformThroughDeformations) {
  const double R = 300.0;
  const SurfaceMesh sphere = testing::sphereMesh(R, 4);
  expectFlowKeepsUniform(sphere, [](Vec3 x) { return Vec3(x.x(), x.y(), 1.8 * x.z()); }, "stretched sphere");
  expectFlowKeepsUniform(
      sphere, [&](Vec3 x) { return Vec3(x * (1.0 + 0.3 * x.x() * x.y() / (R * R) + 0.2 * x.z() / R)); },
      "lumpy sphere");
  expectFlowKeepsUniform(
      testing::patchMesh(1200.0, 20.0),
      [](Vec3 x) {
        const double r2 = (x.x() - 600.0) * (x.x() - 600.0) + (x.y() - 600.0) * (x.y() - 600.0);
        return Vec3(x.x(), x.y(), x.z() + 300.0 * std::exp(-r2 / (150.0 * 150.0)));
      },
      "patch with a bump");
}

// A uniform dilation stretches every cell alike: no lipid flows, no copy moves.
TEST(LipidFlow, AUniformDilationMovesNoCopy) {
  SurfaceMesh m = testing::sphereMesh(300.0, 3);
  std::vector<int> copies = testing::dropCopiesByArea(m, 50L * m.numVertices(), 4);
  const std::vector<int> start = copies;
  const std::vector<double> before = dualCellAreas(m);
  for (Vec3& x : m.positions()) x *= 1.2;
  RandomStream random(1, StreamId::kCopyTransport);
  const LipidFlowStats stats = carryWithLipidFlow(m, before, dualCellAreas(m), {&copies}, random);
  EXPECT_EQ(stats.substeps, 0);
  EXPECT_EQ(copies, start);
}

}  // namespace
}  // namespace cortex
