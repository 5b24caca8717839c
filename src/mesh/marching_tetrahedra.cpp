#include "mesh/marching_tetrahedra.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "mesh/mesh_improvement.hpp"
#include "mesh/soup_cleanup.hpp"
#include "mesh/surface_mesh.hpp"
#include "mesh/surface_smoothing.hpp"

namespace cortex {
namespace {

using Offset = std::array<int, 3>;
using NodeId = std::int64_t;

// Freudenthal split of a cube into 6 tetrahedra, one per axis order (a, b, c): corners
// 000 -> e_a -> e_a + e_b -> 111. Every cube uses the same main diagonal, so the faces of
// neighbouring tetrahedra match and the extracted surface is closed. Corners of each tet
// are in increasing componentwise order, which the edge keys below rely on.
constexpr std::array<std::array<int, 3>, 6> kAxisOrders = {
    {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

std::array<Offset, 4> tetCorners(const std::array<int, 3>& order) {
  std::array<Offset, 4> c{};
  for (int step = 1; step < 4; ++step) {
    c[step] = c[step - 1];
    c[step][order[step - 1]] = 1;
  }
  return c;
}

int det(const Offset& a, const Offset& b, const Offset& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

Offset minus(const Offset& a, const Offset& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

constexpr double kMaxNodesPerLayer = 1e8;  // 800 MB per layer of doubles

class TetMesher {
 public:
  TetMesher(const ImplicitSurface& surface, double spacing)
      : surface_(surface), h_(spacing), eps_(1e-6 * spacing) {
    const int pad = 2;
    origin_ = surface.box_min - Vec3::Constant(pad * h_);
    const Vec3 cells = ((surface.box_max - surface.box_min) / h_).array().ceil() + 2 * pad;
    // Two layers of values are held; refuse grids whose layers would not fit in memory.
    if (!((cells.x() + 1) * (cells.y() + 1) <= kMaxNodesPerLayer)) {
      throw InputError(fmt::format("marchingTetrahedra: spacing {} is too fine for a box of "
                                   "{} x {} (more than {:g} grid nodes per layer)",
                                   h_, cells.x() * h_, cells.y() * h_, kMaxNodesPerLayer));
    }
    for (int axis = 0; axis < 3; ++axis) nodes_[axis] = static_cast<NodeId>(cells[axis]) + 1;
  }

  TriangleSoup run() {
    const NodeId layer_size = nodes_[0] * nodes_[1];
    // Only two z-layers of values are kept, so memory grows with the area of the box.
    std::vector<double> lower(layer_size), upper(layer_size);
    fillLayer(0, upper);
    for (NodeId k = 0; k + 1 < nodes_[2]; ++k) {
      std::swap(lower, upper);
      fillLayer(k + 1, upper);
      for (NodeId j = 0; j + 1 < nodes_[1]; ++j) {
        for (NodeId i = 0; i + 1 < nodes_[0]; ++i) marchCube({i, j, k}, lower, upper);
      }
    }
    return std::move(soup_);
  }

 private:
  Vec3 position(const std::array<NodeId, 3>& n) const {
    return origin_ + h_ * Vec3(double(n[0]), double(n[1]), double(n[2]));
  }
  NodeId id(const std::array<NodeId, 3>& n) const {
    return (n[2] * nodes_[1] + n[1]) * nodes_[0] + n[0];
  }

  void fillLayer(NodeId k, std::vector<double>& layer) const {
    for (NodeId j = 0; j < nodes_[1]; ++j) {
      for (NodeId i = 0; i < nodes_[0]; ++i) {
        const Vec3 x = position({i, j, k});
        double f = surface_.value(x);
        if (!std::isfinite(f)) {
          throw InputError(fmt::format(
              "marchingTetrahedra: implicit function is not finite at ({}, {}, {})", x.x(),
              x.y(), x.z()));
        }
        // A node exactly on the surface would put several crossings on one point and
        // create zero-area triangles; pushing it slightly outside keeps them apart.
        if (std::abs(f) < eps_) f = eps_;
        layer[j * nodes_[0] + i] = f;
      }
    }
  }

  void marchCube(const std::array<NodeId, 3>& base, const std::vector<double>& lower,
                 const std::vector<double>& upper) {
    double corner[2][2][2];
    bool any_inside = false, any_outside = false;
    for (int dz = 0; dz < 2; ++dz) {
      const std::vector<double>& layer = dz == 0 ? lower : upper;
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          const double f = layer[(base[1] + dy) * nodes_[0] + base[0] + dx];
          corner[dz][dy][dx] = f;
          (f < 0.0 ? any_inside : any_outside) = true;
        }
      }
    }
    if (!any_inside || !any_outside) return;
    for (const auto& order : kAxisOrders) {
      const std::array<Offset, 4> c = tetCorners(order);
      std::array<double, 4> f{};
      for (int q = 0; q < 4; ++q) f[q] = corner[c[q][2]][c[q][1]][c[q][0]];
      marchTet(base, c, f);
    }
  }

  // Vertex on the tet edge p-q (p < q in corner order), shared through the grid edge key.
  Index crossing(const std::array<NodeId, 3>& base, const std::array<Offset, 4>& c,
                 const std::array<double, 4>& f, int p, int q) {
    if (p > q) std::swap(p, q);
    const std::array<NodeId, 3> lo{base[0] + c[p][0], base[1] + c[p][1], base[2] + c[p][2]};
    const Offset dir = minus(c[q], c[p]);
    const NodeId key = id(lo) * 8 + (dir[0] | dir[1] << 1 | dir[2] << 2);
    const auto [it, inserted] = vertex_of_edge_.try_emplace(key, Index(soup_.positions.size()));
    if (inserted) {
      const Vec3 a = position(lo);
      const Vec3 b = a + h_ * Vec3(dir[0], dir[1], dir[2]);
      const double t = f[p] / (f[p] - f[q]);
      soup_.positions.push_back(a + t * (b - a));
    }
    return it->second;
  }

  // Orientation is decided from the exact integer corner offsets, not from the (possibly
  // tiny) triangle normals, so it cannot be flipped by round-off.
  void marchTet(const std::array<NodeId, 3>& base, const std::array<Offset, 4>& c,
                const std::array<double, 4>& f) {
    std::array<int, 4> in{}, out{};
    int n_in = 0, n_out = 0;
    for (int q = 0; q < 4; ++q) (f[q] < 0.0 ? in[n_in++] : out[n_out++]) = q;
    auto cross = [&](int p, int q) { return crossing(base, c, f, p, q); };
    if (n_in == 1 || n_in == 3) {
      const bool lone_inside = n_in == 1;
      const int v = lone_inside ? in[0] : out[0];
      const std::array<int, 4>& rest = lone_inside ? out : in;
      const int a = rest[0], b = rest[1], d = rest[2];
      // The normal of (a, b, d) crossings points away from v iff det(a-v, b-v, d-v) > 0.
      const bool away = det(minus(c[a], c[v]), minus(c[b], c[v]), minus(c[d], c[v])) > 0;
      if (away == lone_inside) {
        soup_.triangles.push_back({cross(v, a), cross(v, b), cross(v, d)});
      } else {
        soup_.triangles.push_back({cross(v, a), cross(v, d), cross(v, b)});
      }
    } else if (n_in == 2) {
      const int i0 = in[0], i1 = in[1], o0 = out[0], o1 = out[1];
      // Quad (i0o0, i0o1, i1o1, i1o0) faces outward iff det(o0-i0, o1-i0, i1-i0) > 0.
      std::array<Index, 4> quad{cross(i0, o0), cross(i0, o1), cross(i1, o1), cross(i1, o0)};
      if (det(minus(c[o0], c[i0]), minus(c[o1], c[i0]), minus(c[i1], c[i0])) < 0) {
        std::swap(quad[1], quad[3]);
      }
      const auto& x = soup_.positions;
      const double diag02 = (x[quad[0]] - x[quad[2]]).squaredNorm();
      const double diag13 = (x[quad[1]] - x[quad[3]]).squaredNorm();
      const int s = diag02 <= diag13 ? 0 : 1;  // cut along the shorter diagonal
      soup_.triangles.push_back({quad[s], quad[s + 1], quad[s + 2]});
      soup_.triangles.push_back({quad[s], quad[s + 2], quad[(s + 3) % 4]});
    }
  }

  const ImplicitSurface& surface_;
  double h_;
  double eps_;
  Vec3 origin_;
  std::array<NodeId, 3> nodes_{};
  std::unordered_map<NodeId, Index> vertex_of_edge_;
  TriangleSoup soup_;
};

// Measured on spheres and ellipsoids (R = 1000, edges 20-200): the mean edge of the
// Freudenthal surface is 0.52-0.55 grid spacings, so spacing = 1.9 x target gives a mean
// edge within 1% of target (5% for the coarsest meshes). Twenty sweeps bring the minimum
// angle from ~0 to about 20-23 degrees; more sweeps gain about 1 degree per 30.
constexpr double kSpacingPerEdge = 1.9;
constexpr int kSmoothingIterations = 20;

}  // namespace

TriangleSoup marchingTetrahedra(const ImplicitSurface& surface, double spacing) {
  if (!(spacing > 0.0) || !surface.value) {
    throw InputError("marchingTetrahedra: spacing must be > 0 and the function set");
  }
  if (!((surface.box_max - surface.box_min).minCoeff() >= 0.0)) {
    throw InputError("marchingTetrahedra: bounding box has box_max < box_min");
  }
  TriangleSoup soup = TetMesher(surface, spacing).run();
  weldCloseVertices(soup, 1e-9 * spacing);
  return soup;
}

TriangleSoup meshImplicitSurface(const ImplicitSurface& surface, double target_edge) {
  if (!(target_edge > 0.0)) {
    throw InputError(
        fmt::format("meshImplicitSurface: target edge must be > 0 (got {})", target_edge));
  }
  TriangleSoup soup = marchingTetrahedra(surface, kSpacingPerEdge * target_edge);
  const std::string too_coarse =
      fmt::format("meshImplicitSurface: target edge {} is too coarse: ", target_edge);
  if (soup.triangles.empty()) throw InputError(too_coarse + "the grid misses the shape");
  smoothOnSurface(soup, surface, target_edge, kSmoothingIterations);
  // Raw marching-tetrahedra valences (3 to 8) bias the curvature estimators by ~2.5%
  // however fine the mesh; flipping towards valence 6 removes that bias.
  SurfaceMesh mesh = SurfaceMesh::fromSoup(soup, "marching tetrahedra");
  improveMesh(mesh, [&](const Vec3& x) { return surface.project(x); }, 10);
  soup = {mesh.positions(), mesh.triangles()};
  if (const std::size_t inverted = countInvertedTriangles(soup, surface); inverted > 0) {
    throw InputError(too_coarse + std::to_string(inverted) +
                     " triangles face inward where the shape is thinner than the mesh resolves");
  }
  return soup;
}

}  // namespace cortex
