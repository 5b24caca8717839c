// The Sobolev preconditioner (membrane/sobolev_preconditioner.hpp) inverts the operator it
// states, with and without its low-rank part, and its mesh operators are the cotan
// Laplacian and lumped vertex areas.
#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "membrane/sobolev_preconditioner.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

using constants::kPi;

struct Fixture {
  SurfaceMesh mesh = testing::sphereMesh(500.0, 3, 0.1);
  std::vector<double> x = flatCoordinates(mesh.positions());
  ScalarMeshOperators ops = scalarMeshOperators(x.data(), mesh.numVertices(), mesh.triangles());
  double kappa = 100.0, eps = 20.0 / (500.0 * 500.0);

  // P0 = κ K M⁻¹ K, K = L + εM, written out.
  Eigen::MatrixXd operatorP0() const {
    Eigen::SparseMatrix<double> k = ops.stiffness;
    for (Index i = 0; i < mesh.numVertices(); ++i) k.coeffRef(i, i) += eps * ops.mass[i];
    const Eigen::MatrixXd kd(k);
    return kappa * kd * ops.mass.cwiseInverse().asDiagonal() * kd;
  }
};

TEST(SobolevPreconditioner, MeshOperatorsAreTheCotanLaplacianAndVertexAreas) {
  const Fixture f;
  const Index n = f.mesh.numVertices();
  // Constants are the Laplacian's null space; the vertex areas sum to the mesh area
  // (within 1% of the sphere's: the perturbed icosphere is a fine inscribed polyhedron).
  EXPECT_LT((f.ops.stiffness * Eigen::VectorXd::Ones(n)).norm(), 1e-9);
  EXPECT_NEAR(f.ops.mass.sum() / (4 * kPi * 500.0 * 500.0), 1.0, 0.01);
  // The Dirichlet energy uᵀLu ≈ ∫|∇_S z|² dA. z = x₃/R is an l = 1 harmonic on the
  // sphere (−Δz = 2z/R²), so ∫|∇_S z|² = 2/R² ∫z² dA = 8π/3 for any R (2%: mesh error).
  Eigen::VectorXd z(n);
  for (Index v = 0; v < n; ++v) z[v] = f.x[3 * v + 2] / 500.0;
  EXPECT_NEAR(z.dot(f.ops.stiffness * z) / (8.0 * kPi / 3.0), 1.0, 0.02);
}

TEST(SobolevPreconditioner, InvertsItsOperator) {
  const Fixture f;
  SobolevPreconditioner p;
  p.build(f.ops, f.kappa, f.eps, {});
  ASSERT_TRUE(p.ok());
  const Eigen::VectorXd z = Eigen::VectorXd::Random(f.mesh.numVertices());
  EXPECT_LT((p.apply(Eigen::VectorXd(f.operatorP0() * z)) - z).norm(), 1e-8 * z.norm());
}

TEST(SobolevPreconditioner, AppliesItsLowRankPartExactly) {
  const Fixture f;
  const Index n = f.mesh.numVertices();
  SobolevPreconditioner p;
  p.build(f.ops, f.kappa, f.eps, {});
  // A low-rank part as large as P0 itself (as the stiff area and volume penalties are):
  // enough to change the solution completely, not so large that round-off dominates.
  const Eigen::MatrixXd p0 = f.operatorP0();
  const Eigen::MatrixXd u = Eigen::MatrixXd::Random(n, 2);
  const Eigen::VectorXd w = Eigen::Vector2d(3.0, 0.5) * (p0.norm() / u.squaredNorm());
  p.setLowRank(u, w);
  const Eigen::MatrixXd full = p0 + u * w.asDiagonal() * u.transpose();
  const Eigen::MatrixXd z = Eigen::MatrixXd::Random(n, 3);
  EXPECT_LT((p.apply(Eigen::MatrixXd(full * z)) - z).norm(), 1e-8 * z.norm());
  // and differs from P0's inverse
  EXPECT_GT((p.apply(Eigen::MatrixXd(p0 * z)) - z).norm(), 1e-3 * z.norm());
}

// Fixed dofs are identity rows: the rest is the operator restricted to the free dofs.
TEST(SobolevPreconditioner, DecouplesFixedDofs) {
  const Fixture f;
  const Index n = f.mesh.numVertices();
  std::vector<char> fixed(static_cast<std::size_t>(n), 0);
  for (Index v = 0; v < n; v += 7) fixed[static_cast<std::size_t>(v)] = 1;
  SobolevPreconditioner p;
  p.build(f.ops, f.kappa, f.eps, fixed);
  ASSERT_TRUE(p.ok());
  Eigen::VectorXd r = Eigen::VectorXd::Random(n);
  for (Index v = 0; v < n; ++v) {
    if (fixed[static_cast<std::size_t>(v)]) r[v] = 0.0;
  }
  const Eigen::VectorXd z = p.apply(r);
  for (Index v = 0; v < n; ++v) {
    if (fixed[static_cast<std::size_t>(v)]) {
      EXPECT_EQ(z[v], 0.0) << v;
    }
  }
  EXPECT_GT(z.norm(), 0.0);
}

}  // namespace
}  // namespace cortex
