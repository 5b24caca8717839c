// Cylinder stretching: E = sum_cylinders k_s/2 (|x1 - x0| - l0)^2, k_s from the type.
#pragma once

#include <string>
#include <vector>

#include "filament/filament_layout.hpp"
#include "filament/filament_params.hpp"
#include "mech/energy_term.hpp"

namespace cortex {

class FilamentStretchingEnergy final : public EnergyTerm {
 public:
  // Both are held by reference: the network rebuilds the layout in place.
  FilamentStretchingEnergy(const FilamentLayout& layout, const std::vector<FilamentType>& types)
      : layout_(layout), types_(types) {}
  const std::string& name() const override;
  const std::string& owner() const override;
  double evaluate(const Evaluation& e) override;

 private:
  const FilamentLayout& layout_;
  const std::vector<FilamentType>& types_;
};

}  // namespace cortex
