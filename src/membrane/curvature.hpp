// Discrete mean curvature at a vertex from the gradients of area and volume.
//
//   signed   (thesis eq. 2.8, Surface Evolver "star_perp"):  H = <gA, gV> / (2 <gV, gV>)
//   unsigned (thesis eq. 2.9):                               H = |gA| / (2 |gV|)
// Both give H = 1/R on a sphere of radius R with outward orientation.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "mesh/geometry.hpp"

namespace cortex {

enum class CurvatureEstimator { kSigned, kUnsigned };

struct CurvatureAndDerivative {
  double H;
  // dH/dx_p = J_A(p)^T alpha + J_V(p)^T beta, with J_A, J_V the Jacobians of the
  // vertex's area and volume gradients with respect to x_p.
  Vec3 alpha, beta;
};

// Inline: called once per vertex per force evaluation in the bending loop.
inline CurvatureAndDerivative meanCurvature(const Vec3& ga, const Vec3& gv, CurvatureEstimator estimator) {
  if (estimator == CurvatureEstimator::kSigned) {
    const double d = 2.0 * gv.squaredNorm();
    const double h = ga.dot(gv) / d;
    return {h, gv / d, (ga - 4.0 * h * gv) / d};
  }
  const double na = ga.norm(), nv = gv.norm();
  const double h = na / (2.0 * nv);
  // |gA| has no derivative where gA = 0 (a flat vertex); H² has, and it is zero there,
  // which is the derivative the bending energy needs at H0 = 0 (0 is also a subgradient
  // of H there). Without this case a flat patch's forces were 0/0.
  if (na == 0.0) return {0.0, Vec3::Zero(), Vec3::Zero()};
  return {h, ga / (2.0 * na * nv), -h * gv / (nv * nv)};
}

// Mean curvature of every vertex for output: the estimator's value with the sign of
// <gA, gV> (so the unsigned estimator still tells concave from convex); zero on
// boundary vertices, where it is undefined.
std::vector<double> vertexMeanCurvature(const MeshGeometry& g, const MeshTopology& topo,
                                        CurvatureEstimator estimator);

}  // namespace cortex
