#include "filament/filament.hpp"

#include <algorithm>

namespace cortex {

std::pair<Index, double> Filament::locate(double s) const {
  const auto it = std::upper_bound(lattice.begin(), lattice.end() - 1, s,
                                   [](double v, std::int64_t l) { return v < static_cast<double>(l); });
  const Index i = std::clamp<Index>(static_cast<Index>(it - lattice.begin()) - 1, 0, numCylinders() - 1);
  const double lo = static_cast<double>(lattice[i]), hi = static_cast<double>(lattice[i + 1]);
  return {i, std::clamp((s - lo) / (hi - lo), 0.0, 1.0)};
}

Vec3 Filament::pointAt(double s) const {
  const auto [i, w] = locate(s);
  return (1.0 - w) * beads[i] + w * beads[i + 1];
}

Vec3 Filament::plusDirection() const { return (beads.back() - beads[beads.size() - 2]).normalized(); }
Vec3 Filament::minusDirection() const { return (beads.front() - beads[1]).normalized(); }

double Filament::length() const {
  double l = 0.0;
  for (std::size_t i = 1; i < beads.size(); ++i) l += (beads[i] - beads[i - 1]).norm();
  return l;
}

Filament makeStraightFilament(Index type, const Vec3& minus_end, const Vec3& direction, std::int64_t monomers,
                              int cylinder_monomers, double monomer_size) {
  Filament f;
  f.type = type;
  for (std::int64_t m = 0;; m += cylinder_monomers) {
    const std::int64_t at = std::min(m, monomers);
    f.lattice.push_back(at);
    f.beads.push_back(minus_end + static_cast<double>(at) * monomer_size * direction);
    if (at == monomers) break;
  }
  return f;
}

}  // namespace cortex
