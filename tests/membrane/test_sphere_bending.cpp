// Helfrich energy of a sphere against the closed form 8*pi*kappa, for both curvature
// estimators, on icospheres and on marching-tetrahedra meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/constants.hpp"
#include "membrane/bending_energy.hpp"
#include "mesh/implicit_shapes.hpp"
#include "mesh/marching_tetrahedra.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

constexpr double kKappa = 100.0;  // pN nm
const double k8PiKappa = 8.0 * constants::kPi * kKappa;

double bendingEnergy(const SurfaceMesh& mesh, CurvatureEstimator estimator) {
  Membrane membrane("sphere", mesh, {}, {});
  BendingEnergy term(membrane, {Schedule(kKappa), Schedule(0.0), estimator});
  const std::vector<double> x = flatCoordinates(mesh.positions());
  return term.evaluate({x.data(), nullptr, 1});
}

double meanEdge(const SurfaceMesh& m) {
  double sum = 0.0;
  for (Index h = 0; h < m.numHalfedges(); ++h) sum += (m.positions()[m.tip(h)] - m.positions()[m.tail(h)]).norm();
  return sum / m.numHalfedges();
}

// Surface Evolver's published star_perp figures (docs/membrane.md): the signed estimator over-estimates 8 pi kappa on projected
// icospheres by 1.28e-2, 3.22e-3, 8.1e-4, 2.0e-4 at 162, 642, 2562, 10242 vertices. The
// references carry 2-3 significant digits, hence the 3% relative tolerance.
TEST(SphereBending, SignedEstimatorMatchesPublishedIcosphereErrors) {
  const double expected[] = {1.28e-2, 3.22e-3, 8.1e-4, 2.0e-4};
  for (int level = 2; level <= 5; ++level) {
    const double e = bendingEnergy(testing::sphereMesh(1000.0, level), CurvatureEstimator::kSigned);
    const double error = e / k8PiKappa - 1.0;
    EXPECT_NEAR(error, expected[level - 2], 0.03 * expected[level - 2]) << "level " << level;
  }
}

// The discrete energy is scale invariant, exactly as 8 pi kappa is independent of R.
TEST(SphereBending, EnergyIsIndependentOfRadius) {
  for (auto est : {CurvatureEstimator::kSigned, CurvatureEstimator::kUnsigned}) {
    const double small = bendingEnergy(testing::sphereMesh(10.0, 3), est);
    const double large = bendingEnergy(testing::sphereMesh(5000.0, 3), est);
    EXPECT_NEAR(small, large, 1e-9 * large);
  }
}

// Issue acceptance: within 1% of 8 pi kappa for mesh_size <= R/20, both estimators, on the
// meshes cortex actually generates (marching tetrahedra + smoothing) and on icospheres.
// Also prints the convergence table quoted in docs/membrane.md.
TEST(SphereBending, WithinOnePercentForMeshSizeBelowRadiusOverTwenty) {
  const double R = 1000.0;
  std::printf("%-22s %10s %9s %12s %12s\n", "mesh", "vertices", "edge/R", "signed err", "unsigned err");
  for (double fraction : {1.0 / 10, 1.0 / 20, 1.0 / 40}) {
    const SurfaceMesh mt = SurfaceMesh::fromSoup(
        meshImplicitSurface(implicitSphere(Vec3(3000, 3000, 3000), R), fraction * R), "mt sphere");
    const double es = bendingEnergy(mt, CurvatureEstimator::kSigned) / k8PiKappa - 1.0;
    const double eu = bendingEnergy(mt, CurvatureEstimator::kUnsigned) / k8PiKappa - 1.0;
    std::printf("%-22s %10d %9.4f %12.3e %12.3e\n", "marching tetrahedra", mt.numVertices(), meanEdge(mt) / R, es, eu);
    if (fraction <= 1.0 / 20) {
      EXPECT_LT(std::abs(es), 0.01) << "signed, mesh_size R/" << 1 / fraction;
      EXPECT_LT(std::abs(eu), 0.01) << "unsigned, mesh_size R/" << 1 / fraction;
    }
  }
  for (int level = 2; level <= 5; ++level) {
    const SurfaceMesh ico = testing::sphereMesh(R, level);
    const double es = bendingEnergy(ico, CurvatureEstimator::kSigned) / k8PiKappa - 1.0;
    const double eu = bendingEnergy(ico, CurvatureEstimator::kUnsigned) / k8PiKappa - 1.0;
    std::printf("%-22s %10d %9.4f %12.3e %12.3e\n", "icosphere", ico.numVertices(), meanEdge(ico) / R, es, eu);
    if (meanEdge(ico) <= R / 20) {
      EXPECT_LT(std::abs(es), 0.01);
      EXPECT_LT(std::abs(eu), 0.01);
    }
  }
}

}  // namespace
}  // namespace cortex

namespace cortex {
namespace {

TEST(FlatBending, AnExactlyFlatPatchHasZeroFiniteForcesWithEitherEstimator) {
  // |∇A| = 0 at a flat vertex: the unsigned estimator's H = |∇A|/(2|∇V|) has no
  // derivative there, H² has (zero). Its forces were 0/0 = NaN, which a relaxation took
  // for "converged" (a flat patch pushed by a filament never moved).
  const SurfaceMesh mesh = testing::patchMesh(200.0, 20.0);
  Membrane membrane("patch", mesh, {}, {});
  for (auto estimator : {CurvatureEstimator::kSigned, CurvatureEstimator::kUnsigned}) {
    BendingEnergy term(membrane, {Schedule(100.0), Schedule(0.0), estimator});
    const std::vector<double> x = flatCoordinates(mesh.positions());
    std::vector<double> g(x.size(), 0.0);
    EXPECT_EQ(term.evaluate({x.data(), g.data(), 1}), 0.0);
    for (double v : g) {
      ASSERT_TRUE(std::isfinite(v));
      EXPECT_EQ(v, 0.0);
    }
  }
}

}  // namespace
}  // namespace cortex
