// Harmonic springs between points on two cylinders (bound linkers and motors):
// E = sum k/2 (|pb - pa| - l0)^2 with p = (1 - w) x[bead0] + w x[bead1].
#pragma once

#include <string>
#include <vector>

#include "filament/filament_layout.hpp"
#include "filament/filament_term.hpp"

namespace cortex {

// Position of a cylinder point, beads numbered from `bead_offset` in x.
Vec3 cylinderPoint(const CylinderPoint& p, const double* x, Index bead_offset);

// k (|pb - pa| - l0): positive when the spring is stretched (pN). For force-dependent
// unbinding and walking rates.
double springTension(const Spring& s, const double* x, Index bead_offset);

class SpringEnergy final : public FilamentTerm {
 public:
  // `springs` is one of the layout's lists (linkers or motors), held by reference;
  // `bead_offset` is read from `layout` at each evaluation.
  SpringEnergy(const FilamentLayout& layout, const std::vector<Spring>& springs, std::string name)
      : FilamentTerm(layout, std::move(name)), springs_(springs) {}
  double evaluate(const Evaluation& e) override;
  // Each spring's tension springTension at coordinates x (the whole coordinate vector).
  std::vector<double> tensions(const double* x) const;

 private:
  const std::vector<Spring>& springs_;
};

}  // namespace cortex
