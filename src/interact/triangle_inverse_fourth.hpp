// The integral of 1/d⁴ over a triangle, d the distance from a point p to the points of
// the triangle: the kernel of the membrane–filament excluded volume of the thesis
// (eq. 2.13, E = k_excl Σ_t ∫_t dS / d⁴, appendix A.5), in closed form, with its exact
// gradient with respect to the point and the three vertices.
//
// Closed form. With n̂ the unit normal, h = (p − a)·n̂ the height of p over the plane and
// q its foot, the triangle is the signed sum of the three triangles (q, A, B) over its
// edges AB. In polar coordinates about q, an edge at in-plane distance d from q (positive
// on the triangle's side) seen between t1 = (A − p)·ê and t2 = (B − p)·ê along it gives
//   ∫_(q,A,B) dS/(r² + h²)² = d / (2 h² s) · [atan(t2/s) − atan(t1/s)],  s = √(d² + h²),
// and for a plane (every edge far away) the sum tends to π/h².
//
// When q lies outside the triangle by more than h (in-plane distance δ > h), the edge
// terms are each of order 1/h² and cancel (the boundary's winding number about q is 0).
// There the sum is evaluated as
//   Σ sgn(d) · ½[G(t2) − G(t1)],
//   G(t) = −atan(t/s)/(s(|d| + s)) + atan(z)/h²,  z = −t h²/((|d| + s)(s|d| + t²)),
// which is each edge term minus its planar angle over 2h², rewritten without
// cancellation (both parts are h² times well-conditioned factors; atan(z)/h² by its
// series for small z); every vertex is then more than h from q, so no term is singular.
// Otherwise (q over the triangle or within h of it) the direct sum has no cancellation
// and no singular term: at a foot on a vertex or an edge line the split form's terms
// blow up (their derivatives reach 1e13 and more) while their sum stays smooth.
// Differences atan(t2/s) − atan(t1/s) are taken as one arctangent,
// atan2(s(t2 − t1), s² + t1 t2): for a point far along an edge's line both are near ±π/2
// and the plain difference loses up to 1e-8 of the result (a skinny triangle seen from 15
// edge lengths away). A point on the triangle (h = 0, δ = 0) gives +infinity: the energy
// there is infinite, and callers back off.
//
// Gradients: forward-mode automatic differentiation of the same expressions (Eigen's
// AutoDiffScalar) in as many directions as asked for, exact to rounding and checked
// against central differences in tests.
#pragma once

#include <array>

#include "core/types.hpp"

namespace cortex {

// ∫_triangle(a,b,c) dS / |p − x|⁴ in 1/length² (1/nm² with nm input).
double triangleInverseFourth(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

struct TriangleInverseFourth {
  double value = 0.0;
  Vec3 d_point = Vec3::Zero();                              // ∂/∂p
  std::array<Vec3, 3> d_vertices{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};  // ∂/∂a, ∂/∂b, ∂/∂c
};
// Which derivatives to compute: the point's alone (a filament relaxed against a held
// membrane; 2.3× as fast; d_vertices stay zero), or the point's and the vertices'. The
// point's alone are other instructions than the point's of the whole gradient and may
// differ from them in the last bits.
enum class InverseFourthGradient { kPoint, kAll };
TriangleInverseFourth triangleInverseFourthWithGradient(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                                        InverseFourthGradient which = InverseFourthGradient::kAll);

}  // namespace cortex
