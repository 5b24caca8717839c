#include "interact/triangle_queries.hpp"

namespace cortex {

TrianglePoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto at = [&](double wa, double wb, double wc) { return TrianglePoint{wa * a + wb * b + wc * c, {wa, wb, wc}}; };
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return at(1, 0, 0);
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return at(0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return at(1 - t, t, 0);
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return at(0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return at(1 - t, 0, t);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return at(0, 1 - t, t);
  }
  const double denom = va + vb + vc;
  if (!(denom > 0.0)) return at(1, 0, 0);  // degenerate: every region test above failed on rounding
  return at(va / denom, vb / denom, vc / denom);
}

namespace {
// Six times the signed volume of tetrahedron (a, b, c, d).
double orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a);
}
}  // namespace

bool segmentMeetsTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  // The segment's ends on either side of (or on) the triangle's plane...
  const double sp = orientation(a, b, c, p), sq = orientation(a, b, c, q);
  if ((sp > 0.0 && sq > 0.0) || (sp < 0.0 && sq < 0.0)) return false;
  if (sp == 0.0 && sq == 0.0) return false;  // in the plane: no crossing from one side to the other
  // ...and the line through them passes inside every edge (the same sign about each).
  const double u = orientation(p, q, a, b), v = orientation(p, q, b, c), w = orientation(p, q, c, a);
  return (u >= 0.0 && v >= 0.0 && w >= 0.0) || (u <= 0.0 && v <= 0.0 && w <= 0.0);
}

}  // namespace cortex
