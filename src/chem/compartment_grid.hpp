// The cubic compartment grid of the 3D chemistry: geometry (where a point lies, where a
// compartment is) and its subvolume graph (face neighbours, hop length h). The engine
// only sees the graph; sim/ and filament/ use the geometry to place events and slices.
#pragma once

#include <array>
#include <vector>

#include "chem/subvolume_graph.hpp"
#include "core/types.hpp"

namespace cortex {

// Avogadro's number in cortex units: copies per µM per fL (1 fL = 1 µm³ = 1e9 nm³).
inline constexpr double kCopiesPerMicromolarFemtoliter = 602.214076;
// Copies that make 1 µM in a volume of `volume_nm3` (N_A V).
inline double copiesPerMicromolar(double volume_nm3) { return kCopiesPerMicromolarFemtoliter * volume_nm3 * 1e-9; }

struct CompartmentGrid {
  double size = 500.0;               // nm, cube edge
  std::array<int, 3> shape{1, 1, 1}; // compartments per axis; the box is shape*size from the origin
  Index count() const { return shape[0] * shape[1] * shape[2]; }
  Index index(int i, int j, int k) const { return (k * shape[1] + j) * shape[0] + i; }
  std::array<int, 3> coords(Index c) const { return {c % shape[0], (c / shape[0]) % shape[1], c / (shape[0] * shape[1])}; }
  double volume() const { return size * size * size; }  // nm^3
  Vec3 extent() const { return size * Vec3(shape[0], shape[1], shape[2]); }  // nm, the box's far corner
  double copiesPerMicromolar() const { return cortex::copiesPerMicromolar(volume()); }  // in one compartment
  Vec3 centre(Index c) const {
    const auto ijk = coords(c);
    return Vec3((ijk[0] + 0.5) * size, (ijk[1] + 0.5) * size, (ijk[2] + 0.5) * size);
  }
  // Compartment holding point x (nm), clamped to the box.
  Index locate(const Vec3& x) const;
};

// Faces of a compartment, in the order every per-face array uses.
enum class GridFace : int { kMinusX, kPlusX, kMinusY, kPlusY, kMinusZ, kPlusZ };

// The grid as a subvolume graph: one subvolume of volume h^3 per compartment, a pair of
// directed edges per shared face with hop length^2 h^2 (hop rate D/h^2 per copy, the
// finite-volume rate of Fick's law). Edges of a compartment follow the face order above,
// faces on the box's walls (reflective) have none.
SubvolumeGraph gridGraph(const CompartmentGrid& grid);
// Per-face values (six per compartment, in GridFace order) as one value per directed
// edge of gridGraph(grid), e.g. the fractions of face areas on one side of a membrane.
std::vector<double> gridEdgeValues(const CompartmentGrid& grid, const std::vector<std::array<double, 6>>& per_face);

}  // namespace cortex
