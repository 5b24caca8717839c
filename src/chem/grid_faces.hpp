// Face neighbours of every compartment as a 6-bit mask plus fixed index offsets, so the
// event loop finds a hop's destination with a table look-up instead of divisions.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "chem/chemistry_model.hpp"

namespace cortex {

namespace detail {
// For each 6-bit face mask: how many faces exist, and which is the k-th.
struct FaceTable {
  std::array<std::uint8_t, 64> count{};
  std::array<std::array<std::uint8_t, 6>, 64> face{};
};
constexpr FaceTable makeFaceTable() {
  FaceTable t;
  for (int m = 0; m < 64; ++m)
    for (int f = 0; f < 6; ++f)
      if (m & (1 << f)) t.face[m][t.count[m]++] = static_cast<std::uint8_t>(f);
  return t;
}
inline constexpr FaceTable kFaceTable = makeFaceTable();
}  // namespace detail

class GridFaces {
 public:
  // Faces are numbered -x, +x, -y, +y, -z, +z; bit f of a mask is set when face f has a
  // neighbour (box walls are reflective: a missing face is simply never hopped through).
  explicit GridFaces(const CompartmentGrid& grid);

  std::uint8_t mask(Index c) const { return mask_[c]; }
  static int count(std::uint8_t mask) { return detail::kFaceTable.count[mask]; }
  // Neighbour through the k-th existing face of c (0 <= k < count(mask(c))).
  Index neighbour(Index c, int k) const { return c + offset_[detail::kFaceTable.face[mask_[c]][k]]; }
  // Neighbour through face f, which must exist.
  Index across(Index c, int f) const { return c + offset_[f]; }

 private:
  std::array<Index, 6> offset_{};
  std::vector<std::uint8_t> mask_;
};

}  // namespace cortex
