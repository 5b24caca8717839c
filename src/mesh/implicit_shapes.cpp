#include "mesh/implicit_shapes.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/error.hpp"

namespace cortex {

Vec3 ImplicitSurface::gradientAt(const Vec3& x) const {
  if (gradient) return gradient(x);
  // Step relative to the shape size: small enough for accuracy near a surface that is
  // about as curved as the box is large, far above round-off of the coordinates.
  const double h = 1e-6 * std::max((box_max - box_min).norm(), 1e-300);
  Vec3 g;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 forward = x, backward = x;
    forward[axis] += h;
    backward[axis] -= h;
    g[axis] = (value(forward) - value(backward)) / (2.0 * h);
  }
  return g;
}

Vec3 ImplicitSurface::project(Vec3 x, int newton_steps) const {
  for (int step = 0; step < newton_steps; ++step) {
    const Vec3 g = gradientAt(x);
    const double g2 = g.squaredNorm();
    if (!(g2 > 0.0)) break;
    const Vec3 next = x - (value(x) / g2) * g;
    if (!next.allFinite()) break;
    x = next;
  }
  return x;
}

ImplicitSurface implicitSphere(const Vec3& center, double radius) {
  if (!(radius > 0.0)) {
    throw InputError(fmt::format("implicitSphere: radius must be > 0 (got {})", radius));
  }
  ImplicitSurface s;
  s.value = [center, radius](const Vec3& x) { return (x - center).norm() - radius; };
  s.gradient = [center](const Vec3& x) -> Vec3 {
    const Vec3 d = x - center;
    const double n = d.norm();
    return n > 0.0 ? Vec3(d / n) : Vec3(Vec3::UnitZ());
  };
  s.box_min = center - Vec3::Constant(radius);
  s.box_max = center + Vec3::Constant(radius);
  return s;
}

ImplicitSurface implicitEllipsoid(const Vec3& center, const Vec3& radii) {
  if (!(radii.minCoeff() > 0.0)) {
    throw InputError("implicitEllipsoid: all radii must be > 0");
  }
  const double scale = radii.minCoeff();
  ImplicitSurface s;
  s.value = [center, radii, scale](const Vec3& x) {
    return ((x - center).cwiseQuotient(radii).norm() - 1.0) * scale;
  };
  s.gradient = [center, radii, scale](const Vec3& x) -> Vec3 {
    const Vec3 u = (x - center).cwiseQuotient(radii);
    const double n = u.norm();
    if (n == 0.0) return Vec3::UnitZ();
    return u.cwiseQuotient(radii) * (scale / n);
  };
  s.box_min = center - radii;
  s.box_max = center + radii;
  return s;
}

}  // namespace cortex
