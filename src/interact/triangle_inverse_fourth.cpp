#include "interact/triangle_inverse_fourth.hpp"

#include <unsupported/Eigen/AutoDiff>

#include <cmath>
#include <limits>

#include "interact/triangle_queries.hpp"

namespace cortex {
namespace {

using std::abs;
using std::atan2;
using std::sqrt;

template <class T>
using V3 = Eigen::Matrix<T, 3, 1>;

template <class T>
double valueOf(const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return x;
  } else {
    return x.value();
  }
}

template <class T>
Vec3 valuesOf(const V3<T>& x) {
  return Vec3(valueOf(x[0]), valueOf(x[1]), valueOf(x[2]));
}

// atan(z)/z, by its series where z is small (z = 0 included).
template <class T>
T atanOverArgument(const T& z) {
  if (abs(valueOf(z)) < 1e-3) {
    const T z2 = z * z;
    return 1.0 - z2 * (1.0 / 3.0 - z2 * (1.0 / 5.0 - z2 / 7.0));  // next term z⁸/9 < 1e-25
  }
  return atan2(z, T(1.0)) / z;
}

// atan(t2/s) − atan(t1/s) for s > 0 as one arctangent: the two are close to ±π/2 when
// the point is far along the edge's line, and their difference would lose its digits.
template <class T>
T angleBetween(const T& t1, const T& t2, const T& s) {
  return atan2(T(s * (t2 - t1)), T(s * s + t1 * t2));
}

template <class T>
T integral(const V3<T>& p, const V3<T>& a, const V3<T>& b, const V3<T>& c) {
  const V3<T> normal = (b - a).cross(c - a);
  const T twice_area = normal.norm();
  if (valueOf(twice_area) <= 0.0) return T(0.0);  // a degenerate triangle has no area
  const V3<T> n = normal / twice_area;
  const T h = (p - a).dot(n);
  const T h2 = h * h;
  const std::array<const V3<T>*, 4> corner{&a, &b, &c, &a};
  std::array<T, 3> d, t1, t2;
  for (int i = 0; i < 3; ++i) {
    const V3<T>& A = *corner[i];
    const V3<T>& B = *corner[i + 1];
    const V3<T> e = (B - A).normalized();
    d[i] = (p - A).dot(n.cross(e));  // positive on the triangle's side (counter-clockwise about n)
    t1[i] = (A - p).dot(e);
    t2[i] = (B - p).dot(e);
  }
  // Which form: by the in-plane distance δ from the foot q to the triangle.
  const Vec3 q = valuesOf(p) - valueOf(h) * valuesOf(n);
  const double delta2 = (closestPointOnTriangle(q, valuesOf(a), valuesOf(b), valuesOf(c)).point - q).squaredNorm();
  // A foot within rounding of the triangle counts as on it (the split form needs q
  // truly outside).
  const double on_it = 1e-24 * valueOf(twice_area);
  if (!(delta2 > valueOf(h2) && delta2 > on_it)) {
    // q over the triangle or within h of it: the edge terms add up without cancelling
    // (each is of the size of the result), and none is singular.
    if (!(valueOf(h2) > on_it)) return T(std::numeric_limits<double>::infinity());  // p on the triangle
    T sum(0.0);
    for (int i = 0; i < 3; ++i) {
      const T s = sqrt(d[i] * d[i] + h2);
      sum += d[i] / (2.0 * h2 * s) * angleBetween(t1[i], t2[i], s);
    }
    return sum;
  }
  // q outside by more than h: the terms' 1/h² parts cancel (the winding number is 0), so
  // they are taken out of each term. Every vertex is more than h from q, which keeps
  // s|d| + t² ≥ h²/2 in each term: no singular part.
  T sum(0.0);
  for (int i = 0; i < 3; ++i) {
    // sgn(d)·f(|d|) with f(0) = 0 (t1, t2 on one side of q when d = 0): an odd function
    // of d whose derivative at 0 is f'(0), which |d| would lose there.
    const bool positive = valueOf(d[i]) >= 0.0;
    const T D = positive ? d[i] : T(-d[i]);
    const T s = sqrt(D * D + h2);
    const auto atanPart = [&](const T& t) -> T {  // T, not an AutoDiff expression of temporaries
      const T w = -t / ((D + s) * (s * D + t * t));  // z / h²
      return w * atanOverArgument(T(w * h2));
    };
    const T edge = 0.5 * (atanPart(t2[i]) - atanPart(t1[i]) - angleBetween(t1[i], t2[i], s) / (s * (D + s)));
    sum += positive ? edge : T(-edge);
  }
  return sum;
}

}  // namespace

double triangleInverseFourth(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return integral<double>(p, a, b, c);
}

namespace {

// integral<> differentiated along the point's coordinates (Directions = 4: three and an
// unused fourth, which keeps the derivative vectors one SIMD register wide; 2.3× the pairs
// per second of 12 in bench/triangle_integral.cpp, where 3 was slower than 4) or along
// all twelve coordinates (Directions = 12; 9 for the vertices alone was slower still).
template <int Directions>
Eigen::AutoDiffScalar<Eigen::Matrix<double, Directions, 1>> differentiated(const Vec3& p, const Vec3& a,
                                                                            const Vec3& b, const Vec3& c) {
  using Derivatives = Eigen::Matrix<double, Directions, 1>;
  using Scalar = Eigen::AutoDiffScalar<Derivatives>;
  const std::array<const Vec3*, 4> input{&p, &a, &b, &c};
  const int variables = Directions == 12 ? 4 : 1;  // points differentiated along, from p on
  std::array<V3<Scalar>, 4> x;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 3; ++j)
      x[k][j] = k < variables ? Scalar((*input[k])[j], Directions, 3 * k + j)
                              : Scalar((*input[k])[j], Derivatives::Zero());
  return integral<Scalar>(x[0], x[1], x[2], x[3]);
}

}  // namespace

TriangleInverseFourth triangleInverseFourthWithGradient(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                                        InverseFourthGradient which) {
  TriangleInverseFourth out;
  if (which == InverseFourthGradient::kPoint) {
    const auto value = differentiated<4>(p, a, b, c);
    out.value = value.value();
    if (std::isfinite(out.value)) out.d_point = value.derivatives().template head<3>();
    return out;
  }
  const auto value = differentiated<12>(p, a, b, c);
  out.value = value.value();
  if (!std::isfinite(out.value)) return out;
  out.d_point = value.derivatives().template segment<3>(0);
  for (int k = 0; k < 3; ++k) out.d_vertices[k] = value.derivatives().template segment<3>(3 + 3 * k);
  return out;
}

}  // namespace cortex
