// Cylinder stretching: E = sum_cylinders k_s/2 (|x1 - x0| - l0)^2, k_s from the type.
#pragma once

#include <string>
#include <vector>

#include "filament/filament_layout.hpp"
#include "filament/filament_params.hpp"
#include "filament/filament_term.hpp"

namespace cortex {

class FilamentStretchingEnergy final : public FilamentTerm {
 public:
  // Held by reference: the network rebuilds the layout in place.
  FilamentStretchingEnergy(const FilamentLayout& layout, const std::vector<FilamentType>& types)
      : FilamentTerm(layout, "stretching"), types_(types) {}
  double evaluate(const Evaluation& e) override;

 private:
  const std::vector<FilamentType>& types_;
};

}  // namespace cortex
