// Constrained, preconditioned L-BFGS (mech/constrained_lbfgs.hpp) on problems with known
// minimizers and multipliers.
#include <gtest/gtest.h>

#include <cmath>

#include "mech/constrained_lbfgs.hpp"

namespace cortex {
namespace {

// min 1/2 Σ a_i u_i² − b·u  subject to  Σ u_i = c  (and optionally Σ u_i² = r², a
// nonlinear constraint). Lagrange: a_i u_i − b_i = λ (+ 2 μ u_i).
class Quadratic final : public ConstrainedProblem {
 public:
  Eigen::VectorXd a, b;
  double c = 1.0;
  double radius = -1.0;  // < 0: no sphere constraint
  bool exact_preconditioner = true;
  double forbidden_above = INFINITY;  // u_0 beyond it: infinite energy (a forbidden region)
  Index size() const override { return static_cast<Index>(a.size()); }
  int numConstraints() const override { return radius < 0 ? 1 : 2; }
  double valueAndGradient(const Eigen::VectorXd& u, Eigen::VectorXd& g) override {
    g = a.cwiseProduct(u) - b;
    if (u[0] > forbidden_above) return INFINITY;
    return 0.5 * u.dot(a.cwiseProduct(u)) - b.dot(u);
  }
  void constraints(const Eigen::VectorXd& u, Eigen::VectorXd& cv, Eigen::MatrixXd& jac) override {
    cv.resize(numConstraints());
    jac.resize(numConstraints(), u.size());
    cv[0] = u.sum() - c;
    jac.row(0).setOnes();
    if (radius >= 0) {
      cv[1] = u.squaredNorm() - radius * radius;
      jac.row(1) = 2.0 * u.transpose();
    }
  }
  Eigen::VectorXd constraintScale() const override { return Eigen::VectorXd::Ones(numConstraints()); }
  // The sum row as a linear constraint whose W column is kept between calls, as the
  // membrane's rigid rows are (ConstrainedProblem::keptLinearW); only without the sphere.
  bool keep_linear_w = false;
  Eigen::MatrixXd kept_w;
  int numLinearConstraints() const override { return keep_linear_w ? 1 : 0; }
  const Eigen::MatrixXd* keptLinearW() const override { return kept_w.size() ? &kept_w : nullptr; }
  void keepLinearW(const Eigen::MatrixXd& w) override { kept_w = w; }
  long preconditioner_columns = 0;  // columns P^-1 was applied to
  Eigen::MatrixXd precondition(const Eigen::MatrixXd& r) override {
    preconditioner_columns += r.cols();
    if (!exact_preconditioner) return r;
    return a.cwiseInverse().asDiagonal() * r;
  }
  bool admissible(const Eigen::VectorXd&) override { return true; }
};

// λ of the linear constraint alone: Σ (b_i + λ)/a_i = c.
double linearMultiplier(const Quadratic& q) {
  return (q.c - q.b.cwiseQuotient(q.a).sum()) / q.a.cwiseInverse().sum();
}

ConstrainedLbfgsResult solve(Quadratic& q, Eigen::VectorXd& u, double tolerance, double max_move,
                             bool scale_initial_hessian = false) {
  LbfgsMemory memory;
  ConstrainedLbfgsSettings s;
  s.tolerance = tolerance;
  s.max_move = max_move;
  s.max_iterations = 5000;
  s.scale_initial_hessian = scale_initial_hessian;
  return minimizeConstrained(q, u, s, memory);
}

Quadratic quadratic() {
  Quadratic q;
  q.a = Eigen::VectorXd::LinSpaced(50, 1.0, 1000.0);  // condition number 1000
  q.b = Eigen::VectorXd::LinSpaced(50, -3.0, 5.0);
  q.c = 2.0;
  return q;
}

// Linear constraint: u_i = (b_i + λ)/a_i with λ from Σ u_i = c. Tolerances: the
// minimizer stops at a residual of 1e-10; the solution is then exact to ~1e-10/a_min.
TEST(ConstrainedLbfgs, SolvesAnEqualityConstrainedQuadraticInOneNewtonStep) {
  Quadratic q = quadratic();
  const double lambda = linearMultiplier(q);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(50);
  const ConstrainedLbfgsResult r = solve(q, u, 1e-10, 1e9);
  ASSERT_TRUE(r.converged) << r.stop_reason;
  EXPECT_NEAR(u.sum(), q.c, 1e-10);
  for (Index i = 0; i < 50; ++i) EXPECT_NEAR(u[i], (q.b[i] + lambda) / q.a[i], 1e-9);
  EXPECT_NEAR(r.multipliers[0], lambda, 1e-8);
  EXPECT_LE(r.evaluations, 5);  // the exact Hessian as preconditioner: Newton
}

// Without the preconditioner the same problem takes L-BFGS iterations that grow with the
// condition number; it must still reach the same point.
TEST(ConstrainedLbfgs, ReachesTheSameMinimumUnpreconditioned) {
  Quadratic q = quadratic();
  q.exact_preconditioner = false;
  const double lambda = linearMultiplier(q);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(50);
  const ConstrainedLbfgsResult r = solve(q, u, 1e-9, 1e9, true);
  ASSERT_TRUE(r.converged) << r.stop_reason;
  for (Index i = 0; i < 50; ++i) EXPECT_NEAR(u[i], (q.b[i] + lambda) / q.a[i], 1e-8);
  EXPECT_GT(r.evaluations, 5);
}

// A nonlinear constraint (|u| = r) besides the linear one: the result satisfies the
// stationarity conditions a_i u_i − b_i = λ + 2 μ u_i with both multipliers, and both
// constraints to the restoration's tolerance.
TEST(ConstrainedLbfgs, SatisfiesStationarityWithANonlinearConstraint) {
  Quadratic q = quadratic();
  q.radius = 1.5;
  Eigen::VectorXd u = Eigen::VectorXd::Constant(50, q.c / 50.0);
  u[0] += 1.0, u[1] -= 1.0;  // feasible for the sum; the sphere is restored at the start
  const ConstrainedLbfgsResult r = solve(q, u, 1e-9, 0.5);
  ASSERT_TRUE(r.converged) << r.stop_reason;
  EXPECT_NEAR(u.sum(), q.c, 1e-9);
  EXPECT_NEAR(u.norm(), q.radius, 1e-9);
  const double lambda = r.multipliers[0], mu = r.multipliers[1];
  for (Index i = 0; i < 50; ++i) EXPECT_NEAR(q.a[i] * u[i] - q.b[i], lambda + 2.0 * mu * u[i], 1e-8) << i;
}

// Far off the sphere |u| = r (|u| = 0.29 against r = 1.5): the restoration's chord steps
// alone would crawl, Newton steps take over, and the result is the same constrained
// minimum as from a start close to the sphere.
TEST(ConstrainedLbfgs, RestoresFromFarOffANonlinearConstraint) {
  Quadratic q = quadratic();
  q.radius = 1.5;
  Eigen::VectorXd near = Eigen::VectorXd::Constant(50, q.c / 50.0);
  near[0] += 1.0, near[1] -= 1.0;
  Eigen::VectorXd far = 0.2 * near;  // both constraints violated, the sum 5-fold
  ASSERT_TRUE(solve(q, near, 1e-9, 0.5).converged);
  const ConstrainedLbfgsResult r = solve(q, far, 1e-9, 0.5);
  ASSERT_TRUE(r.converged) << r.stop_reason;
  EXPECT_NEAR(far.norm(), q.radius, 1e-9);
  EXPECT_LT((far - near).cwiseAbs().maxCoeff(), 1e-8);
}

// From the minimum itself (a converged shape confirmed on fresh normals, a membrane the
// filaments did not move) the minimizer stops at once with the right multiplier and
// without a single preconditioner solve: they are the costliest part of a membrane's
// iteration.
TEST(ConstrainedLbfgs, AStartAtTheMinimumNeedsNoPreconditionerSolve) {
  Quadratic q = quadratic();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(50);
  ASSERT_TRUE(solve(q, u, 1e-10, 1e9).converged);
  q.preconditioner_columns = 0;
  const ConstrainedLbfgsResult r = solve(q, u, 1e-9, 1e9);
  ASSERT_TRUE(r.converged) << r.stop_reason;
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(q.preconditioner_columns, 0);
  EXPECT_NEAR(r.multipliers[0], linearMultiplier(q), 1e-8);
  EXPECT_LE(r.max_residual, 1e-9);
}

// W of a linear row kept from a call with another metric (here P = diag(a) of a problem
// whose a differed by up to 2x) is not P^-1 J^T of this one: the projection stays exact
// and the minimum is the same (same tolerances as the first test); the kept column
// spares its solve.
TEST(ConstrainedLbfgs, AKeptLinearColumnFromAnotherMetricReachesTheSameMinimum) {
  Quadratic q = quadratic();
  q.keep_linear_w = true;
  q.kept_w = q.a.cwiseInverse().cwiseProduct(Eigen::VectorXd::LinSpaced(50, 0.5, 2.0));
  Eigen::VectorXd u = Eigen::VectorXd::Zero(50);
  const ConstrainedLbfgsResult r = solve(q, u, 1e-10, 1e9);
  ASSERT_TRUE(r.converged) << r.stop_reason;
  const double lambda = linearMultiplier(q);
  EXPECT_NEAR(u.sum(), q.c, 1e-10);
  for (Index i = 0; i < 50; ++i) EXPECT_NEAR(u[i], (q.b[i] + lambda) / q.a[i], 1e-9);
  EXPECT_NEAR(r.multipliers[0], lambda, 1e-8);
  EXPECT_EQ(q.preconditioner_columns, r.iterations) << "one solve per iteration, none for the kept column";
}

// A restoration that lands in a forbidden region (infinite energy: in a run, a membrane
// pushed onto a filament bead by a volume target) is an infeasible start, u unchanged,
// so that the caller approaches the target in steps (membrane/shape_relaxation.cpp); a
// target whose restoration stays clear of the region is relaxed from there. Without
// this, the line search started from the infinite energy and the run failed
// (mutation-checked).
TEST(ConstrainedLbfgs, ARestorationIntoAForbiddenRegionIsAnInfeasibleStart) {
  Quadratic q = quadratic();
  // From u = 0 the restoration onto sum u = c is u = c a^-1 / sum a^-1 (W = P^-1 J^T).
  const double u0 = q.c / (q.a[0] * q.a.cwiseInverse().sum());
  q.forbidden_above = 0.5 * u0;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(50);
  ConstrainedLbfgsResult r = solve(q, u, 1e-10, 1e9);
  EXPECT_EQ(r.stop_reason, kInfeasibleStart);
  EXPECT_EQ(u, Eigen::VectorXd::Zero(50));
  q.c *= 0.25;  // a quarter of the way: restored u_0 = u0 / 4, clear of the region
  r = solve(q, u, 1e-10, 1e9);
  EXPECT_NE(r.stop_reason, kInfeasibleStart);
  EXPECT_GT(r.iterations, 0);
  EXPECT_LE(u[0], q.forbidden_above);
  EXPECT_NEAR(u.sum(), q.c, 1e-10);
}

}  // namespace
}  // namespace cortex
