#include "sim/filament_feedback.hpp"

#include "sim/system.hpp"

namespace cortex {

FilamentFeedback::FilamentFeedback(FilamentNetwork& network, FilamentTerms terms, FilamentChemistry& chemistry,
                                   EndLoadProbe* end_loads)
    : network_(network), terms_(terms), chemistry_(chemistry), end_loads_(end_loads) {}

void FilamentFeedback::update(System& system) { apply(system.coordinates(), system.forceField()); }

void FilamentFeedback::apply(const Eigen::VectorXd& x, ForceField& force_field) {
  const Eigen::VectorXd forces = force_field.contactForces(x);
  const auto& filaments = network_.filaments();
  std::vector<std::array<Vec3, 2>> end_forces(filaments.size());
  for (std::size_t f = 0; f < filaments.size(); ++f) {
    const Index first = network_.offset() + network_.firstBead(static_cast<Index>(f));
    const Index last = first + static_cast<Index>(filaments[f].beads.size()) - 1;
    end_forces[f] = {Vec3(forces.segment<3>(3 * first)), Vec3(forces.segment<3>(3 * last))};
  }
  // The layout's springs are the bound linkers and motors, in order.
  for (auto [kind, term] : {std::pair{BinderKind::kLinker, terms_.linkers}, std::pair{BinderKind::kMotor, terms_.motors}}) {
    if (!term) continue;
    const std::vector<double> tensions = term->tensions(x.data());
    std::vector<Binding>& bound = network_.bound(kind);
    for (std::size_t i = 0; i < bound.size(); ++i) bound[i].tension = tensions[i];
  }
  if (end_loads_) end_loads_->update();
  chemistry_.update(end_forces);
}

}  // namespace cortex
