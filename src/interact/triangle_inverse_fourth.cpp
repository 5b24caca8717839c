#include "interact/triangle_inverse_fourth.hpp"

#include <unsupported/Eigen/AutoDiff>

#include <cmath>
#include <limits>

#include "core/constants.hpp"

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

// atan(z)/z, by its series where z is small (z = 0 included).
template <class T>
T atanOverArgument(const T& z) {
  if (abs(valueOf(z)) < 1e-3) {
    const T z2 = z * z;
    return 1.0 - z2 * (1.0 / 3.0 - z2 * (1.0 / 5.0 - z2 / 7.0));  // next term z⁸/9 < 1e-25
  }
  return atan2(z, T(1.0)) / z;
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
  double reach2 = 0.0;  // largest squared in-plane distance from q to a vertex
  for (int i = 0; i < 3; ++i) {
    const V3<T>& A = *corner[i];
    const V3<T>& B = *corner[i + 1];
    const V3<T> e = (B - A).normalized();
    d[i] = (p - A).dot(n.cross(e));  // positive on the triangle's side (counter-clockwise about n)
    t1[i] = (A - p).dot(e);
    t2[i] = (B - p).dot(e);
    const V3<T> in_plane = A - p + h * n;
    reach2 = std::max(reach2, valueOf(in_plane.squaredNorm()));
  }
  if (valueOf(h2) >= reach2) {
    // Far from the plane: the edge terms do not cancel much.
    T sum(0.0);
    for (int i = 0; i < 3; ++i) {
      const T s = sqrt(d[i] * d[i] + h2);
      sum += d[i] / (2.0 * h2 * s) * (atan2(t2[i], s) - atan2(t1[i], s));
    }
    return sum;
  }
  // Near the plane: the winding part apart, exactly.
  bool outside = false, boundary = false;
  for (int i = 0; i < 3; ++i) {
    outside = outside || valueOf(d[i]) < 0.0;
    boundary = boundary || valueOf(d[i]) == 0.0;
  }
  double winding = outside ? 0.0 : 2.0 * constants::kPi;
  if (!outside && boundary) {
    // q on an edge or a vertex: the angle the rest of the boundary subtends at q.
    winding = 0.0;
    for (int i = 0; i < 3; ++i)
      if (valueOf(d[i]) > 0.0) winding += std::atan2(valueOf(t2[i]), valueOf(d[i])) - std::atan2(valueOf(t1[i]), valueOf(d[i]));
  }
  // In the plane (h = 0) only the edge terms remain outside the triangle; on it, infinity.
  if (valueOf(h2) == 0.0 && winding > 0.0) return T(std::numeric_limits<double>::infinity());
  T sum = winding > 0.0 ? T(winding / (2.0 * h2)) : T(0.0);
  for (int i = 0; i < 3; ++i) {
    if (valueOf(d[i]) == 0.0) continue;  // sgn(d) = 0
    const T D = abs(d[i]);
    const T s = sqrt(D * D + h2);
    const auto G = [&](const T& t) -> T {  // T, not an AutoDiff expression of temporaries
      const T w = -t / ((D + s) * (s * D + t * t));  // z / h²
      return -atan2(t, s) / (s * (D + s)) + w * atanOverArgument(T(w * h2));
    };
    const T edge = 0.5 * (G(t2[i]) - G(t1[i]));
    sum += valueOf(d[i]) > 0.0 ? edge : T(-edge);
  }
  return sum;
}

}  // namespace

double triangleInverseFourth(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return integral<double>(p, a, b, c);
}

TriangleInverseFourth triangleInverseFourthWithGradient(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  using Scalar = Eigen::AutoDiffScalar<Eigen::Matrix<double, 12, 1>>;
  std::array<V3<Scalar>, 4> x;
  const std::array<const Vec3*, 4> input{&p, &a, &b, &c};
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 3; ++j) x[k][j] = Scalar((*input[k])[j], 12, 3 * k + j);
  const Scalar value = integral<Scalar>(x[0], x[1], x[2], x[3]);
  TriangleInverseFourth out;
  out.value = value.value();
  if (!std::isfinite(out.value) || value.derivatives().size() != 12) return out;
  out.d_point = value.derivatives().segment<3>(0);
  for (int k = 0; k < 3; ++k) out.d_vertices[k] = value.derivatives().segment<3>(3 + 3 * k);
  return out;
}

}  // namespace cortex
