// Branch joints: the daughter's minus-end bead held at its site on the mother cylinder,
// E = k_p/2 |x[d0] - p_mother|^2, and its first cylinder held at angle theta0 to the
// mother cylinder, E = K (cos theta - cos theta0)^2.
#pragma once

#include <string>

#include "filament/filament_layout.hpp"
#include "filament/filament_term.hpp"

namespace cortex {

class BranchEnergy final : public FilamentTerm {
 public:
  explicit BranchEnergy(const FilamentLayout& layout) : FilamentTerm(layout, "branching") {}
  double evaluate(const Evaluation& e) override;

 private:
};

}  // namespace cortex
