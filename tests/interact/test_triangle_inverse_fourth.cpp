// The closed-form ∫ dS/d⁴ over a triangle (issue 13): against adaptive quadrature at
// 1,000+ random points, near-coplanar (h down to 1/1000 of the triangle) and near-edge
// ones included (relative error < 1e-8),
// against the values the issue states (0.186942034 nm⁻² for the bead at (2,2,3) over the
// right triangle of legs 10; π/h² for an unbounded plane), and its gradient against
// central differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>

#include "core/constants.hpp"
#include "interact/triangle_inverse_fourth.hpp"

namespace cortex {
namespace {

// Gauss–Legendre nodes and weights on [0, 1] (Newton on the Legendre recurrence).
struct GaussLegendre {
  std::vector<double> x, w;
  explicit GaussLegendre(int n) {
    for (int i = 1; i <= n; ++i) {
      double z = std::cos(constants::kPi * (i - 0.25) / (n + 0.5)), dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double step = p1 / dp;
        z -= step;
        if (std::abs(step) < 1e-16) break;
      }
      x.push_back(0.5 * (1.0 - z));
      w.push_back(1.0 / ((1.0 - z * z) * dp * dp));
    }
  }
};

// ∫ g over [lo, hi] by 10-point Gauss–Legendre, bisected adaptively until halving
// changes the estimate by less than `tol` (absolute); throws past a budget of
// evaluations rather than hang.
struct Adaptive1d {
  long evaluations = 0;
  double integrate(const std::function<double(double)>& g, double lo, double hi, double tol) {
    return refine(g, lo, hi, rule(g, lo, hi), tol, 0);
  }
  double rule(const std::function<double(double)>& g, double lo, double hi) {
    static const GaussLegendre gl(10);
    double sum = 0.0;
    for (std::size_t i = 0; i < gl.x.size(); ++i) sum += gl.w[i] * g(lo + (hi - lo) * gl.x[i]);
    if ((evaluations += 10) > 200000000) throw std::runtime_error("quadrature: evaluation budget exhausted");
    return sum * (hi - lo);
  }
  double refine(const std::function<double(double)>& g, double lo, double hi, double whole, double tol, int depth) {
    const double mid = 0.5 * (lo + hi);
    const double left = rule(g, lo, mid), right = rule(g, mid, hi);
    const double change = std::abs(left + right - whole);
    if (change <= tol || change <= 1e-15 * std::abs(left + right) || depth > 60) return left + right;
    return refine(g, lo, mid, left, 0.5 * tol, depth + 1) + refine(g, mid, hi, right, 0.5 * tol, depth + 1);
  }
};

Vec3 closestOnSegment(const Vec3& p, const Vec3& u, const Vec3& v) {
  const double t = std::clamp((p - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
  return u + t * (v - u);
}

// The triangle's point nearest to p.
Vec3 nearestPoint(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a).normalized();
  const Vec3 q = p - (p - a).dot(n) * n;
  const std::array<Vec3, 3> v{a, b, c};
  bool inside = true;
  for (int i = 0; i < 3; ++i) inside = inside && (v[(i + 1) % 3] - v[i]).cross(q - v[i]).dot(n) >= 0;
  if (inside) return q;
  Vec3 nearest = closestOnSegment(q, a, b);
  for (int i = 1; i < 3; ++i) {
    const Vec3 x = closestOnSegment(q, v[i], v[(i + 1) % 3]);
    if ((x - q).squaredNorm() < (nearest - q).squaredNorm()) nearest = x;
  }
  return nearest;
}

// Reference ∫ dS/|p − x|⁴ by nested adaptive quadrature, independent of the closed form:
// the triangle is cut into the fan of triangles (x*, B, C) about its point x* nearest to
// p, where the integrand peaks, and each is mapped to rays from x* to the far edge,
// x = x* + r (B + s(C − B) − x*), dS = 2 area r dr ds: the inner integral over r resolves
// the peak near x*, the outer one over s its angular profile.
double quadrature(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double relative) {
  const Vec3 apex = nearestPoint(p, a, b, c);
  const double scale = 1.0 / std::pow((p - apex).squaredNorm(), 2) * 0.5 * (b - a).cross(c - a).norm();
  Adaptive1d quad;
  double sum = 0.0;
  for (const auto& [u, w] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
    const double twice_area = (u - apex).cross(w - apex).norm();
    if (twice_area <= 1e-14 * (w - u).squaredNorm()) continue;  // x* on this edge
    const auto along = [&](double s) {
      const Vec3 ray = u + s * (w - u) - apex;
      const auto radial = [&](double r) { return r / std::pow((apex + r * ray - p).squaredNorm(), 2); };
      return quad.integrate(radial, 0.0, 1.0, 1e-3 * relative * scale / twice_area);
    };
    sum += twice_area * quad.integrate(along, 0.0, 1.0, relative * scale / (3 * twice_area));
  }
  return sum;
}

TEST(TriangleInverseFourth, TheIssuesValueAndThePlaneLimit) {
  const Vec3 a(0, 0, 0), b(10, 0, 0), c(0, 10, 0);
  EXPECT_NEAR(triangleInverseFourth(Vec3(2, 2, 3), a, b, c), 0.186942034, 5e-10);
  // A triangle much larger than the height: π/h² less the far field ~ O(h²/L²)·π/h².
  const double h = 0.5, L = 1e5;
  const double plane = triangleInverseFourth(Vec3(1, 2, h), Vec3(-L, -L, 0), Vec3(2 * L, -L, 0), Vec3(-L, 2 * L, 0));
  EXPECT_NEAR(plane * h * h / constants::kPi, 1.0, 1e-9);
  // Symmetric in the side of the plane and in the orientation of the triangle.
  EXPECT_DOUBLE_EQ(triangleInverseFourth(Vec3(2, 2, -3), a, b, c), triangleInverseFourth(Vec3(2, 2, 3), a, b, c));
  EXPECT_NEAR(triangleInverseFourth(Vec3(2, 2, 3), a, c, b), 0.186942034, 5e-10);
}

TEST(TriangleInverseFourth, MatchesAdaptiveQuadratureAtRandomPoints) {
  std::mt19937_64 rng(20261130);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), positive(0.0, 1.0);
  int cases = 0;
  double worst = 0.0;
  for (int k = 0; k < 1200; ++k) {
    // A random triangle of edge ~10 nm, some of them skinny.
    const Vec3 a(10 * unit(rng), 10 * unit(rng), 10 * unit(rng));
    const Vec3 b = a + Vec3(10 * unit(rng), 10 * unit(rng), 10 * unit(rng));
    Vec3 c = a + Vec3(10 * unit(rng), 10 * unit(rng), 10 * unit(rng));
    if (k % 5 == 0) c = a + (0.6 + 0.3 * positive(rng)) * (b - a) + 0.05 * Vec3(unit(rng), unit(rng), unit(rng));
    const Vec3 normal = (b - a).cross(c - a).normalized();
    // Points: anywhere nearby; near the plane, inside and outside (h from 1 nm down to
    // 0.01 nm, a thousandth of the triangle); within 1 pm (in the plane) of an edge.
    const double w1 = 1.5 * positive(rng) - 0.25, w2 = 1.5 * positive(rng) - 0.25;
    const Vec3 in_plane = a + w1 * (b - a) + w2 * (c - a);
    const Vec3 across_ab = normal.cross(b - a).normalized();
    Vec3 p;
    switch (k % 4) {
      case 0: p = a + Vec3(15 * unit(rng), 15 * unit(rng), 15 * unit(rng)); break;
      case 1: p = in_plane + std::pow(10.0, -2.0 * positive(rng)) * (unit(rng) < 0 ? -normal : normal); break;
      case 2:
        p = a + positive(rng) * (b - a) + 1e-3 * unit(rng) * across_ab + std::pow(10.0, -1.0 - positive(rng)) * normal;
        break;
      default: p = in_plane + 0.3 * unit(rng) * normal; break;
    }
    const double exact = triangleInverseFourth(p, a, b, c);
    const double height = std::abs((p - a).dot(normal));
    if (height < 1e-2) continue;  // closer, the reference quadrature's cost explodes (the limits are tested below)
    double reference = 0.0;
    try {
      reference = quadrature(p, a, b, c, 1e-11);
    } catch (const std::runtime_error& e) {
      FAIL() << "case " << k << " (h = " << height << "): " << e.what();
    }
    const double error = std::abs(exact - reference) / std::abs(reference);
    worst = std::max(worst, error);
    ++cases;
    ASSERT_LT(error, 1e-8) << "case " << k << ": p = " << p.transpose() << ", a = " << a.transpose()
                           << ", b = " << b.transpose() << ", c = " << c.transpose() << ": " << exact << " vs "
                           << reference;
  }
  EXPECT_GE(cases, 1000);
  RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(TriangleInverseFourth, NearThePlaneAgreesWithTheFarFormula) {
  // The two forms meet at h = reach; just below and above must agree to rounding, and
  // very near the plane the value keeps its π/h² (inside) or finite (outside) behaviour.
  const Vec3 a(0, 0, 0), b(10, 0, 0), c(0, 10, 0);
  for (const Vec3& q : {Vec3(2, 2, 0), Vec3(-3, 4, 0), Vec3(5, 5, 0), Vec3(12, -1, 0)}) {
    double reach = 0.0;
    for (const Vec3& v : {a, b, c}) reach = std::max(reach, (v - q).norm());
    const double below = triangleInverseFourth(q + Vec3(0, 0, reach * (1 - 1e-12)), a, b, c);
    const double above = triangleInverseFourth(q + Vec3(0, 0, reach * (1 + 1e-12)), a, b, c);
    EXPECT_NEAR(below / above, 1.0, 1e-10) << q.transpose();
  }
  const double inside = triangleInverseFourth(Vec3(2, 2, 1e-6), a, b, c);
  EXPECT_NEAR(inside * 1e-12 / constants::kPi, 1.0, 1e-6);
  const double outside = triangleInverseFourth(Vec3(-3, 4, 1e-9), a, b, c);
  const double in_plane = triangleInverseFourth(Vec3(-3, 4, 0), a, b, c);
  EXPECT_TRUE(std::isfinite(in_plane));
  EXPECT_NEAR(outside / in_plane, 1.0, 1e-9);
  EXPECT_EQ(triangleInverseFourth(Vec3(2, 2, 0), a, b, c), std::numeric_limits<double>::infinity());
}

TEST(TriangleInverseFourth, GradientMatchesCentralDifferences) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    std::array<Vec3, 4> x;  // p, a, b, c
    for (Vec3& v : x) v = Vec3(10 * unit(rng), 10 * unit(rng), 10 * unit(rng));
    if (k % 2) x[0] = (x[1] + x[2] + x[3]) / 3 + 0.05 * (x[2] - x[1]).cross(x[3] - x[1]).normalized();  // near the plane
    const TriangleInverseFourth g = triangleInverseFourthWithGradient(x[0], x[1], x[2], x[3]);
    const double value = triangleInverseFourth(x[0], x[1], x[2], x[3]);
    EXPECT_NEAR(g.value, value, 1e-12 * value);  // the same expressions, rounded in another order
    // Steps well below the scale the integrand varies on (the height near the plane),
    // and Richardson extrapolation of two central differences: truncation error O(step⁴).
    const Vec3 normal = (x[2] - x[1]).cross(x[3] - x[1]).normalized();
    const double scale_length = std::min(std::abs((x[0] - x[1]).dot(normal)), 1.0);
    const auto central = [&](int point, int axis, double step) {
      std::array<Vec3, 4> plus = x, minus = x;
      plus[point][axis] += step;
      minus[point][axis] -= step;
      return (triangleInverseFourth(plus[0], plus[1], plus[2], plus[3]) -
              triangleInverseFourth(minus[0], minus[1], minus[2], minus[3])) /
             (2 * step);
    };
    for (int point = 0; point < 4; ++point)
      for (int axis = 0; axis < 3; ++axis) {
        const double step = 1e-2 * scale_length;
        const double numeric = (4 * central(point, axis, step / 2) - central(point, axis, step)) / 3;
        const double analytic = point == 0 ? g.d_point[axis] : g.d_vertices[point - 1][axis];
        double scale = g.d_point.norm();
        for (const Vec3& d : g.d_vertices) scale = std::max(scale, d.norm());
        EXPECT_NEAR(analytic, numeric, 1e-6 * scale) << "case " << k << ", point " << point << ", axis " << axis;
      }
  }
}

}  // namespace
}  // namespace cortex
