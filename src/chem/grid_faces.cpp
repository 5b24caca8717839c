#include "chem/grid_faces.hpp"

namespace cortex {

GridFaces::GridFaces(const CompartmentGrid& grid) {
  const Index sx = 1, sy = grid.shape[0], sz = grid.shape[0] * grid.shape[1];
  offset_ = {-sx, sx, -sy, sy, -sz, sz};
  mask_.resize(grid.count());
  for (int k = 0; k < grid.shape[2]; ++k)
    for (int j = 0; j < grid.shape[1]; ++j)
      for (int i = 0; i < grid.shape[0]; ++i) {
        const std::array<bool, 6> has = {i > 0, i + 1 < grid.shape[0], j > 0, j + 1 < grid.shape[1],
                                         k > 0, k + 1 < grid.shape[2]};
        std::uint8_t m = 0;
        for (int f = 0; f < 6; ++f) m |= static_cast<std::uint8_t>(has[f] << f);
        mask_[grid.index(i, j, k)] = m;
      }
}

}  // namespace cortex
