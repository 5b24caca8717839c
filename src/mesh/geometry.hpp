// Geometry derived from vertex positions, computed once per coordinate update and
// shared by every energy term of a membrane.
//
// Conventions (triangle t = (a, b, c), counter-clockwise seen from outside):
//   n_t = (b - a) x (c - a),  A_t = |n_t| / 2,  e_k = edge opposite corner k, running
//   counter-clockwise (e_a = c - b, e_b = a - c, e_c = b - a).
//   dA_t/dx_k = 1/2 n̂_t x e_k;   vertex area A_v = 1/3 sum of its triangles' areas;
//   volume V = 1/6 sum (a-p).((b-p)x(c-p)) for a fixed point p;  dV/dx_v = 1/6 sum n_t.
// dV/dx_v is the exact gradient on closed meshes and on interior vertices of open ones.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "mesh/mesh_topology.hpp"

namespace cortex {

struct MeshGeometry {
  std::vector<Vec3> face_unit_normal;
  std::vector<double> face_area;
  std::vector<double> vertex_area;
  std::vector<Vec3> area_gradient;    // dA_total / dx_v
  std::vector<Vec3> volume_gradient;  // dV_total / dx_v
  double area = 0.0;
  double volume = 0.0;  // signed; meaningful for closed meshes

  // x points at 3*n coordinates (x0,y0,z0,x1,...).
  void compute(const MeshTopology& topo, const double* x);
};

// Total area and signed volume alone, summed exactly as MeshGeometry::compute sums them:
// what checking an area or volume constraint needs, at a fraction of compute's cost (no
// per-vertex gather).
double totalArea(const MeshTopology& topo, const double* x);
double signedVolume(const MeshTopology& topo, const double* x);

inline Vec3 vertexAt(const double* x, Index v) { return Vec3(x[3 * v], x[3 * v + 1], x[3 * v + 2]); }

// Edge vectors e_k of a triangle (opposite corner k, counter-clockwise).
struct TriangleEdges {
  Vec3 e[3];
  TriangleEdges(const Vec3& a, const Vec3& b, const Vec3& c) : e{c - b, a - c, b - a} {}
};

}  // namespace cortex
