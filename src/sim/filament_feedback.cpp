#include "sim/filament_feedback.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Geometry>

#include "core/error.hpp"
#include "sim/system.hpp"

namespace cortex {

FilamentFeedback::FilamentFeedback(FilamentNetwork& network, FilamentTerms terms, FilamentChemistry& chemistry,
                                   EndLoadProbe* end_loads)
    : network_(network), terms_(terms), chemistry_(chemistry), end_loads_(end_loads) {}

void FilamentFeedback::update(System& system) {
  checkWithinGrid(system.grid(), system.time());
  apply(system.coordinates(), system.forceField());
}

void FilamentFeedback::checkWithinGrid(const CompartmentGrid& grid, double t) const {
  const double slack = kLargestReachOutsideGrid * grid.size;
  const Eigen::AlignedBox3d box(Vec3::Constant(-slack), grid.extent() + Vec3::Constant(slack));
  const auto& filaments = network_.filaments();
  for (std::size_t f = 0; f < filaments.size(); ++f)
    for (const Vec3& x : filaments[f].beads) {
      if (box.contains(x)) continue;
      const double beyond = (x - x.cwiseMax(Vec3::Zero()).cwiseMin(grid.extent())).norm();
      throw RunError(fmt::format(
          "t = {:.6g} s: filament {} reached [{:.1f}, {:.1f}, {:.1f}] nm, {:.3g} nm outside the compartment grid (the "
          "box from [0, 0, 0] to [{}] nm; {:g} of a compartment, {:g} nm, is tolerated), where its ends and sites "
          "would exchange copies with the grid's edge compartment: widen [compartments], or hold the filaments in "
          "with a [boundary]",
          t, f, x.x(), x.y(), x.z(), beyond, fmt::join(grid.extent(), ", "), kLargestReachOutsideGrid, slack));
    }
}

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
