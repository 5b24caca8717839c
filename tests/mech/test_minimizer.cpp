// Both minimizers on functions with known minima, and their failure guards.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.hpp"
#include "mech/minimizer.hpp"

namespace cortex {
namespace {

// f = sum_i c_i (x_i - i)^2 / 2 with condition number 1e4: minimum at x_i = i.
class IllConditionedQuadratic final : public Objective {
 public:
  explicit IllConditionedQuadratic(int n) : c_(n) {
    for (int i = 0; i < n; ++i) c_[i] = std::pow(1e4, static_cast<double>(i) / (n - 1));
  }
  double value(const Eigen::VectorXd& x) override {
    double f = 0;
    for (int i = 0; i < x.size(); ++i) f += 0.5 * c_[i] * (x[i] - i) * (x[i] - i);
    return f;
  }
  double valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) override {
    g.resize(x.size());
    for (int i = 0; i < x.size(); ++i) g[i] = c_[i] * (x[i] - i);
    return value(x);
  }

 private:
  std::vector<double> c_;
};

// value() through valueAndGradient(), for test functions whose gradient is cheap.
class ValueFromGradient : public Objective {
 public:
  double value(const Eigen::VectorXd& x) final {
    Eigen::VectorXd g;
    return valueAndGradient(x, g);
  }
};

// Extended Rosenbrock: minimum 0 at x = (1, ..., 1), a curved narrow valley.
class Rosenbrock final : public ValueFromGradient {
 public:
  double valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) override {
    g.setZero(x.size());
    double f = 0;
    for (int i = 0; i + 1 < x.size(); i += 2) {
      const double a = x[i + 1] - x[i] * x[i], b = 1 - x[i];
      f += 100 * a * a + b * b;
      g[i] += -400 * a * x[i] - 2 * b;
      g[i + 1] += 200 * a;
    }
    return f;
  }
};

class Linear final : public Objective {  // unbounded below
 public:
  double value(const Eigen::VectorXd& x) override { return -x.sum(); }
  double valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) override {
    g = Eigen::VectorXd::Constant(x.size(), -1.0);
    return value(x);
  }
};

class NotANumber final : public Objective {
 public:
  double value(const Eigen::VectorXd&) override { return std::nan(""); }
  double valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) override {
    g.setZero(x.size());
    return value(x);
  }
};

class Minimizers : public ::testing::TestWithParam<MinimizerKind> {
 protected:
  MinimizerSettings settings(double tol) const {
    MinimizerSettings s;
    s.kind = GetParam();
    s.force_tolerance = tol;
    s.max_iterations = 20000;
    s.max_step = 1.0;
    return s;
  }
};

TEST_P(Minimizers, ReachIllConditionedQuadraticMinimum) {
  IllConditionedQuadratic f(51);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(51);
  const MinimizationResult r = minimize(f, x, settings(1e-8));
  ASSERT_TRUE(r.converged) << r.stop_reason;
  for (int i = 0; i < 51; ++i) EXPECT_NEAR(x[i], i, 1e-8);  // |g_i| <= 1e-8 and c_i >= 1
}

TEST_P(Minimizers, FollowTheRosenbrockValley) {
  Rosenbrock f;
  Eigen::VectorXd x(18);
  for (int i = 0; i < 18; ++i) x[i] = i % 2 ? 1.0 : -1.2;
  const MinimizationResult r = minimize(f, x, settings(1e-7));
  ASSERT_TRUE(r.converged) << r.stop_reason;
  // Near the minimum the Hessian's smallest eigenvalue is ~0.4, so |x-1| <~ 1e-7/0.4.
  EXPECT_LT((x - Eigen::VectorXd::Ones(18)).cwiseAbs().maxCoeff(), 1e-6);
}

TEST_P(Minimizers, RefuseAnEnergyUnboundedBelow) {
  Linear f;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
  MinimizerSettings s = settings(1e-3);
  s.max_step = 1e8;
  EXPECT_THROW(minimize(f, x, s), RunError);
}

TEST_P(Minimizers, RefuseANonFiniteEnergy) {
  NotANumber f;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(minimize(f, x, settings(1e-3)), RunError);
}

TEST_P(Minimizers, StopAtMaxIterationsWithoutConverging) {
  Rosenbrock f;
  Eigen::VectorXd x(6);
  x << -1.2, 1.0, -1.2, 1.0, -1.2, 1.0;
  MinimizerSettings s = settings(1e-12);
  s.max_iterations = 3;
  const MinimizationResult r = minimize(f, x, s);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 3);
}

// Springs pulling each of 40 points towards its own anchor with a stiffness that differs
// per point and per axis, seen in a rotated frame: the minimizer stops when the force on
// every point, a 3-vector, is below the tolerance, whatever the axes.
class RotatedAnisotropicSprings final : public ValueFromGradient {
 public:
  explicit RotatedAnisotropicSprings(const Eigen::Matrix3d& rotation) : r_(rotation), k_(3, 40), a_(3, 40) {
    for (int p = 0; p < 40; ++p)
      for (int d = 0; d < 3; ++d) k_(d, p) = std::pow(30.0, ((p * 7 + d * 13) % 40) / 39.0), a_(d, p) = p + 0.5 * d;
  }
  double valueAndGradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) override {
    g.resize(x.size());
    double f = 0;
    for (int p = 0; p < 40; ++p) {
      const Eigen::Vector3d u = r_.transpose() * x.segment<3>(3 * p) - a_.col(p);  // body frame
      f += 0.5 * u.dot(k_.col(p).cwiseProduct(u));
      g.segment<3>(3 * p) = r_ * k_.col(p).cwiseProduct(u);
    }
    return f;
  }

 private:
  Eigen::Matrix3d r_;
  Eigen::Matrix3Xd k_, a_;
};

TEST_P(Minimizers, ConvergeOnTheForceOnEachPointInAnyFrame) {
  const double tol = 1e-3;
  for (const Eigen::Matrix3d& rotation :
       {Eigen::Matrix3d::Identity().eval(),
        Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix()}) {
    RotatedAnisotropicSprings f(rotation);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(120), g;
    const MinimizationResult r = minimize(f, x, settings(tol));
    ASSERT_TRUE(r.converged) << r.stop_reason;
    f.valueAndGradient(x, g);
    double largest = 0;
    for (int p = 0; p < 40; ++p) largest = std::max(largest, g.segment<3>(3 * p).norm());
    EXPECT_LE(largest, tol);  // the vector, not only each of its components
    EXPECT_DOUBLE_EQ(r.max_force, largest);
  }
}

TEST(MaxPointForce, IsTheLargestNormOfAPointsForce) {
  Eigen::VectorXd g(6);
  g << 0.6, -0.6, 0.6, 0.0, 0.9, 0.0;
  EXPECT_DOUBLE_EQ(detail::maxPointForce(g), std::sqrt(3 * 0.36));  // the first point, not |0.9|
  g[4] = std::nan("");
  EXPECT_EQ(detail::maxPointForce(g), std::numeric_limits<double>::infinity());
  EXPECT_THROW(detail::maxPointForce(Eigen::VectorXd::Zero(4)), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(CgAndLbfgs, Minimizers,
                         ::testing::Values(MinimizerKind::kConjugateGradient, MinimizerKind::kLbfgs),
                         [](const auto& info) {
                           return info.param == MinimizerKind::kLbfgs ? std::string("lbfgs") : std::string("cg");
                         });

}  // namespace
}  // namespace cortex
