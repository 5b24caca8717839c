#include "chem/compartment_slicing.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace cortex {
namespace {

using Polygon = std::vector<Vec3>;

// Keeps the part of `poly` with sign * (x[axis] - value) <= 0 (Sutherland-Hodgman).
Polygon clip(const Polygon& poly, int axis, double value, double sign) {
  Polygon out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = poly[i];
    const Vec3& b = poly[(i + 1) % n];
    const double da = sign * (a[axis] - value), db = sign * (b[axis] - value);
    if (da <= 0.0) out.push_back(a);
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// Area vector (normal * area) and area-weighted centroid of a planar polygon.
void accumulate(const Polygon& poly, Vec3& area_vector, Vec3& weighted_centroid, double& area) {
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const Vec3 cross = (poly[i] - poly[0]).cross(poly[i + 1] - poly[0]);
    const double a = 0.5 * cross.norm();
    area_vector += 0.5 * cross;
    weighted_centroid += a * (poly[0] + poly[i] + poly[i + 1]) / 3.0;
    area += a;
  }
}

struct Cut {
  Vec3 area_vector = Vec3::Zero();
  Vec3 weighted_centroid = Vec3::Zero();
  double area = 0.0;
};

// Area of the square [0,h]^2 (in the two axes other than `axis`, at coordinate `level`
// along it) with (x - p).n < 0, by clipping the square against the plane.
double faceAreaInside(int axis, double level, double h, const Vec3& p, const Vec3& n) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  Polygon square(4, Vec3::Zero());
  const double corners[4][2] = {{0, 0}, {h, 0}, {h, h}, {0, h}};
  for (int k = 0; k < 4; ++k) {
    square[k][axis] = level;
    square[k][u] = corners[k][0];
    square[k][v] = corners[k][1];
  }
  Polygon kept;
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec3& a = square[i];
    const Vec3& b = square[(i + 1) % 4];
    const double da = (a - p).dot(n), db = (b - p).dot(n);
    if (da <= 0.0) kept.push_back(a);
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) kept.push_back(a + (b - a) * (da / (da - db)));
  }
  double area = 0.0;
  for (std::size_t i = 1; i + 1 < kept.size(); ++i)
    area += 0.5 * (kept[i] - kept[0]).cross(kept[i + 1] - kept[0]).norm();
  return area;
}

// Inside volume and face areas of the cube [0,h]^3 under the half-space (x - p).n < 0
// (|n| = 1), exactly. Faces by clipping; the volume by the divergence theorem over the
// clipped cube: V = 1/3 sum_faces A_f (x_f . n_f), where the faces at 0 contribute
// nothing, the faces at h contribute h A_{+k}, and the cap A_cap (p.n) with
// A_cap n_k = A_{-k} - A_{+k} (the area vectors of a closed surface sum to zero).
void planarCut(double h, const Vec3& p, const Vec3& n, double& volume, std::array<double, 6>& faces) {
  double sum_plus = 0.0, cap = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double minus = faceAreaInside(k, 0.0, h, p, n), plus = faceAreaInside(k, h, h, p, n);
    faces[2 * k] = minus / (h * h);
    faces[2 * k + 1] = plus / (h * h);
    sum_plus += plus;
    cap += n[k] * (minus - plus);
  }
  volume = std::clamp((h * sum_plus + p.dot(n) * cap) / 3.0 / (h * h * h), 0.0, 1.0);
}

// Inside/outside of every compartment centre: one ray per column along +z; a centre is
// inside when the ray above it crosses the membrane an odd number of times. The ray is
// shifted off the column centre by an irrational fraction of h so that it does not run
// through the vertices and edges of meshes generated on grid-aligned lattices.
std::vector<char> classifyCentres(const std::vector<Vec3>& x, const std::vector<Tri>& triangles,
                                  const CompartmentGrid& grid) {
  const double h = grid.size;
  const double shift_x = 1.234567e-4 * h, shift_y = 2.7182818e-4 * h;
  const int nx = grid.shape[0], ny = grid.shape[1], nz = grid.shape[2];
  std::vector<std::vector<double>> crossings(static_cast<std::size_t>(nx) * ny);
  for (const Tri& t : triangles) {
    const Vec3 &a = x[t[0]], &b = x[t[1]], &c = x[t[2]];
    const double lo_x = std::min({a.x(), b.x(), c.x()}), hi_x = std::max({a.x(), b.x(), c.x()});
    const double lo_y = std::min({a.y(), b.y(), c.y()}), hi_y = std::max({a.y(), b.y(), c.y()});
    const int i0 = std::max(0, static_cast<int>(std::ceil((lo_x - shift_x) / h - 0.5)));
    const int i1 = std::min(nx - 1, static_cast<int>(std::floor((hi_x - shift_x) / h - 0.5)));
    const int j0 = std::max(0, static_cast<int>(std::ceil((lo_y - shift_y) / h - 0.5)));
    const int j1 = std::min(ny - 1, static_cast<int>(std::floor((hi_y - shift_y) / h - 0.5)));
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (det == 0.0) continue;  // vertical triangle: a vertical ray misses it
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double px = (i + 0.5) * h + shift_x, py = (j + 0.5) * h + shift_y;
        const double u = ((px - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (py - a.y())) / det;
        const double v = ((b.x() - a.x()) * (py - a.y()) - (px - a.x()) * (b.y() - a.y())) / det;
        if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
        crossings[static_cast<std::size_t>(j) * nx + i].push_back(a.z() + u * (b.z() - a.z()) + v * (c.z() - a.z()));
      }
  }
  std::vector<char> inside(grid.count(), 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      std::vector<double>& z = crossings[static_cast<std::size_t>(j) * nx + i];
      std::sort(z.begin(), z.end());
      for (int k = 0; k < nz; ++k) {
        const double zc = (k + 0.5) * h;
        const auto above = z.end() - std::upper_bound(z.begin(), z.end(), zc);
        inside[grid.index(i, j, k)] = above % 2 == 1;
      }
    }
  return inside;
}

}  // namespace

CompartmentSlices sliceCompartments(const std::vector<Vec3>& positions, const std::vector<Tri>& triangles,
                                    const CompartmentGrid& grid) {
  const double h = grid.size;
  const Index count = grid.count();
  const std::vector<char> inside = classifyCentres(positions, triangles, grid);
  CompartmentSlices s;
  s.volume.resize(count);
  s.faces.resize(count);
  s.cut.assign(count, 0);
  for (Index c = 0; c < count; ++c) {
    s.volume[c] = inside[c] ? 1.0 : 0.0;
    s.faces[c].fill(s.volume[c]);
  }

  // Membrane parts per compartment, clipped exactly to its box. A map keeps the
  // compartments ordered and the memory proportional to the membrane, not the grid.
  std::map<Index, Cut> cuts;
  for (const Tri& t : triangles) {
    const Polygon tri{positions[t[0]], positions[t[1]], positions[t[2]]};
    std::array<int, 3> lo{}, hi{};
    for (int k = 0; k < 3; ++k) {
      const double mn = std::min({tri[0][k], tri[1][k], tri[2][k]}), mx = std::max({tri[0][k], tri[1][k], tri[2][k]});
      lo[k] = std::max(0, static_cast<int>(std::floor(mn / h)));
      hi[k] = std::min(grid.shape[k] - 1, static_cast<int>(std::floor(mx / h)));
    }
    for (int kz = lo[2]; kz <= hi[2]; ++kz)
      for (int jy = lo[1]; jy <= hi[1]; ++jy)
        for (int ix = lo[0]; ix <= hi[0]; ++ix) {
          const std::array<int, 3> cell{ix, jy, kz};
          Polygon poly = tri;
          for (int k = 0; k < 3 && poly.size() >= 3; ++k) {
            poly = clip(poly, k, cell[k] * h, -1.0);
            if (poly.size() >= 3) poly = clip(poly, k, (cell[k] + 1) * h, 1.0);
          }
          if (poly.size() < 3) continue;
          Cut& cut = cuts[grid.index(ix, jy, kz)];
          accumulate(poly, cut.area_vector, cut.weighted_centroid, cut.area);
        }
  }

  for (const auto& [c, cut] : cuts) {
    const double norm = cut.area_vector.norm();
    // A membrane folded back on itself within one compartment has no plane: keep the
    // centre's classification.
    if (!(cut.area > 0.0) || norm < 1e-6 * cut.area) continue;
    const auto ijk = grid.coords(c);
    const Vec3 corner(ijk[0] * h, ijk[1] * h, ijk[2] * h);
    const Vec3 p = cut.weighted_centroid / cut.area - corner;
    planarCut(h, p, cut.area_vector / norm, s.volume[c], s.faces[c]);
    s.cut[c] = 1;
  }

  // One value per shared face: the mean of what its two compartments computed.
  for (Index c = 0; c < count; ++c) {
    const auto ijk = grid.coords(c);
    for (int k = 0; k < 3; ++k) {
      if (ijk[k] + 1 >= grid.shape[k]) continue;
      std::array<int, 3> n = ijk;
      ++n[k];
      const Index d = grid.index(n[0], n[1], n[2]);
      const double mean = 0.5 * (s.faces[c][2 * k + 1] + s.faces[d][2 * k]);
      s.faces[c][2 * k + 1] = s.faces[d][2 * k] = mean;
    }
  }
  return s;
}

}  // namespace cortex
