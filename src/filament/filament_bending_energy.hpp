// Filament bending at each hinge bead0 -> bead1 -> bead2: E = K (1 - cos theta),
// cos theta = t1.t2 / (|t1| |t2|), t1 = x1 - x0, t2 = x2 - x1, K from the type.
#pragma once

#include <string>
#include <vector>

#include "filament/filament_layout.hpp"
#include "filament/filament_params.hpp"
#include "filament/filament_term.hpp"

namespace cortex {

class FilamentBendingEnergy final : public FilamentTerm {
 public:
  FilamentBendingEnergy(const FilamentLayout& layout, const std::vector<FilamentType>& types)
      : FilamentTerm(layout, "bending"), types_(types) {}
  double evaluate(const Evaluation& e) override;

 private:
  const std::vector<FilamentType>& types_;
};

}  // namespace cortex
