// Base of the membrane energy terms: the membrane they act on and their name.
#pragma once

#include <string>

#include "mech/energy_term.hpp"
#include "membrane/membrane.hpp"

namespace cortex {

class MembraneTerm : public EnergyTerm {
 public:
  MembraneTerm(Membrane& membrane, std::string name) : membrane_(membrane), name_(std::move(name)) {}
  const std::string& name() const override { return name_; }
  const std::string& owner() const override { return membrane_.name(); }

 protected:
  // Gradient block of this membrane inside the global gradient (null if not wanted).
  double* gradientOf(const Evaluation& e) const {
    return e.gradient ? e.gradient + 3 * membrane_.offset() : nullptr;
  }
  Membrane& membrane_;

 private:
  std::string name_;
};

// Adds coefficient * v_i to the gradient of every vertex i.
inline void addScaledVertexField(double* g, const std::vector<Vec3>& field, double coefficient) {
  for (std::size_t i = 0; i < field.size(); ++i)
    for (int k = 0; k < 3; ++k) g[3 * i + k] += coefficient * field[i][k];
}

}  // namespace cortex
