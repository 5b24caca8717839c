// Filament bending at each hinge bead0 -> bead1 -> bead2: E = K (1 - cos theta),
// cos theta = t1.t2 / (|t1| |t2|), t1 = x1 - x0, t2 = x2 - x1, K from the type.
#pragma once

#include <string>
#include <vector>

#include "filament/filament_layout.hpp"
#include "filament/filament_params.hpp"
#include "mech/energy_term.hpp"

namespace cortex {

class FilamentBendingEnergy final : public EnergyTerm {
 public:
  FilamentBendingEnergy(const FilamentLayout& layout, const std::vector<FilamentType>& types)
      : layout_(layout), types_(types) {}
  const std::string& name() const override;
  const std::string& owner() const override;
  double evaluate(const Evaluation& e) override;

 private:
  const FilamentLayout& layout_;
  const std::vector<FilamentType>& types_;
};

}  // namespace cortex
