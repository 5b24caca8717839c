// Shapes given by a signed function (negative inside), the input of marching tetrahedra.
#pragma once

#include <functional>

#include "core/types.hpp"

namespace cortex {

struct ImplicitSurface {
  // Negative inside, positive outside, roughly the signed distance near the surface so
  // that grid spacing and Newton projection behave the same for every shape.
  std::function<double(const Vec3&)> value;
  // Optional analytic gradient; when empty, gradientAt() uses central differences.
  std::function<Vec3(const Vec3&)> gradient;
  // Axis-aligned box containing the whole surface.
  Vec3 box_min = Vec3::Zero();
  Vec3 box_max = Vec3::Zero();

  Vec3 gradientAt(const Vec3& x) const;
  // Newton steps x -= f grad f / |grad f|^2 towards the zero level set; stops early where
  // the gradient vanishes or a step would produce a non-finite point.
  Vec3 project(Vec3 x, int newton_steps = 3) const;
};

ImplicitSurface implicitSphere(const Vec3& center, double radius);

// (|(x - c) / r| - 1) * min(r): its gradient vanishes only at the center, unlike the exact
// distance to an ellipsoid (expensive) or |(x - c)/r|^2 - 1 (badly scaled for thin shapes).
ImplicitSurface implicitEllipsoid(const Vec3& center, const Vec3& radii);

}  // namespace cortex
