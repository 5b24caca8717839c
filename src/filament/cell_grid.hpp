// The shape of a uniform grid of cells over a box, for the cell lists of cylinders
// (excluded_volume_energy.cpp, excluded_volume_end_loads.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "core/types.hpp"

namespace cortex {

struct GridShape {
  double cell;                // nm, the cells' edge
  std::array<Index, 3> dims;  // cells per axis
};

// Cells of edge at least `min_cell` (and 1e-6 nm) over [lo, hi], doubled until there are
// at most 4 per item plus 64, so that a few far-flung items do not make the grid huge.
inline GridShape gridShape(const Vec3& lo, const Vec3& hi, double min_cell, Index items) {
  GridShape g{std::max(min_cell, 1e-6), {}};
  const double max_cells = 4.0 * static_cast<double>(items) + 64.0;
  for (;;) {
    double total = 1.0;
    for (int k = 0; k < 3; ++k) total *= std::floor((hi[k] - lo[k]) / g.cell) + 1.0;
    if (total <= max_cells) break;
    g.cell *= 2.0;
  }
  for (int k = 0; k < 3; ++k) g.dims[k] = static_cast<Index>(std::floor((hi[k] - lo[k]) / g.cell)) + 1;
  return g;
}

}  // namespace cortex
