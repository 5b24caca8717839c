#include "chem/compartment_grid.hpp"

#include <cmath>

namespace cortex {

Index CompartmentGrid::locate(const Vec3& x) const {
  std::array<int, 3> ijk{};
  for (int a = 0; a < 3; ++a) {
    const double u = std::floor(x[a] / size);
    // Written so that NaN lands in the first compartment instead of reaching the cast.
    ijk[a] = u >= 0.0 ? static_cast<int>(std::min(u, static_cast<double>(shape[a] - 1))) : 0;
  }
  return index(ijk[0], ijk[1], ijk[2]);
}

namespace {

// Calls f(face, neighbour) for every face of compartment (i, j, k) that has a neighbour,
// in GridFace order.
template <class F>
void forEachFace(const CompartmentGrid& g, int i, int j, int k, F&& f) {
  const Index c = g.index(i, j, k);
  const Index sx = 1, sy = g.shape[0], sz = g.shape[0] * g.shape[1];
  if (i > 0) f(0, c - sx);
  if (i + 1 < g.shape[0]) f(1, c + sx);
  if (j > 0) f(2, c - sy);
  if (j + 1 < g.shape[1]) f(3, c + sy);
  if (k > 0) f(4, c - sz);
  if (k + 1 < g.shape[2]) f(5, c + sz);
}

template <class F>
void forEachCompartment(const CompartmentGrid& g, F&& f) {
  for (int k = 0; k < g.shape[2]; ++k)
    for (int j = 0; j < g.shape[1]; ++j)
      for (int i = 0; i < g.shape[0]; ++i) f(i, j, k);
}

}  // namespace

SubvolumeGraph gridGraph(const CompartmentGrid& grid) {
  SubvolumeGraph g;
  const double h2 = grid.size * grid.size;
  g.size.assign(static_cast<std::size_t>(grid.count()), grid.volume());
  g.start.reserve(static_cast<std::size_t>(grid.count()) + 1);
  g.lattice = grid.shape;
  forEachCompartment(grid, [&](int i, int j, int k) {
    forEachFace(grid, i, j, k, [&](int, Index neighbour) {
      g.target.push_back(neighbour);
      g.hop_length2.push_back(h2);
    });
    g.start.push_back(static_cast<Index>(g.target.size()));
  });
  return g;
}

std::vector<double> gridEdgeValues(const CompartmentGrid& grid, const std::vector<std::array<double, 6>>& per_face) {
  std::vector<double> out;
  forEachCompartment(grid, [&](int i, int j, int k) {
    const Index c = grid.index(i, j, k);
    forEachFace(grid, i, j, k, [&](int face, Index) { out.push_back(per_face[c][face]); });
  });
  return out;
}

}  // namespace cortex
