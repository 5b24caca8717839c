#include "sim/system.hpp"

#include "filament/boundary_energy.hpp"
#include "filament/branch_energy.hpp"
#include "filament/excluded_volume_energy.hpp"
#include "filament/filament_bending_energy.hpp"
#include "filament/spring_energy.hpp"
#include "filament/stretching_energy.hpp"
#include "membrane/area_energy.hpp"
#include "membrane/bending_energy.hpp"
#include "membrane/regularization_energy.hpp"
#include "membrane/volume_energy.hpp"

namespace cortex {

System::System(std::vector<std::unique_ptr<Membrane>> membranes) : membranes_(std::move(membranes)) {
  buildForceField();
}

void System::buildForceField() {
  force_field_ = ForceField();
  for (auto& m : membranes_) {
    const MembraneMechanics& mech = m->mechanics();
    // Terms whose modulus is zero at all times are left out: they cost time and add nothing.
    if (!mech.bending_modulus.isZero()) force_field_.add(std::make_unique<BendingEnergy>(*m));
    if (!mech.area_modulus.isZero()) {
      if (mech.area_model == AreaModel::kPerVertex)
        force_field_.add(std::make_unique<PerVertexAreaEnergy>(*m));
      else if (mech.area_model == AreaModel::kGlobal)
        force_field_.add(std::make_unique<GlobalAreaEnergy>(*m));
    }
    if (!mech.tension.isZero()) force_field_.add(std::make_unique<TensionEnergy>(*m));
    if (!mech.regularization.isZero()) force_field_.add(std::make_unique<RegularizationEnergy>(*m));
    if (!mech.volume_modulus.isZero() && m->isClosed()) force_field_.add(std::make_unique<VolumeEnergy>(*m));
  }
  layOut();
}

void System::setFilaments(std::unique_ptr<FilamentNetwork> network) {
  filaments_ = std::move(network);
  const FilamentLayout& layout = filaments_->layout();
  const FilamentConfig& config = filaments_->config();
  force_field_.add(std::make_unique<FilamentStretchingEnergy>(layout, config.types));
  force_field_.add(std::make_unique<FilamentBendingEnergy>(layout, config.types));
  force_field_.add(std::make_unique<CylinderExclusionEnergy>(layout, config.types, 40.0));
  if (config.boundary) force_field_.add(std::make_unique<BoundaryRepulsionEnergy>(layout, *config.boundary));
  if (!config.linkers.empty()) force_field_.add(std::make_unique<SpringEnergy>(layout, layout.linkers, "linkers"));
  if (!config.motors.empty()) force_field_.add(std::make_unique<SpringEnergy>(layout, layout.motors, "motors"));
  if (!config.branchers.empty()) force_field_.add(std::make_unique<BranchEnergy>(layout));
  layOut();
}

void System::setFilamentChemistry(std::unique_ptr<FilamentChemistry> chemistry) {
  filament_chemistry_ = std::move(chemistry);
  if (chemistry_) chemistry_->setReactionHook(filament_chemistry_.get());
}

void System::updateMechanochemistry() {
  if (filament_chemistry_ && chemistry_) filament_chemistry_->updateMechanochemistry(*chemistry_);
}

void System::layOut() {
  Index offset = 0;
  std::vector<char> frozen;
  for (auto& m : membranes_) {
    m->setDofOffset(offset);
    offset += m->mesh().numVertices();
    for (char f : m->fixedVertices()) frozen.insert(frozen.end(), 3, f);
  }
  if (filaments_) {
    filaments_->layOut(offset);
    for (const Filament& f : filaments_->filaments())
      for (std::size_t b = 0; b < f.beads.size(); ++b) frozen.insert(frozen.end(), 3, b == 0 && f.minus_anchored);
  }
  force_field_.setFrozen(std::move(frozen));
}

void System::setTime(double t) {
  time_ = t;
  for (auto& m : membranes_) m->setTime(t);
}

Index System::numVertices() const {
  Index n = 0;
  for (const auto& m : membranes_) n += m->mesh().numVertices();
  return n;
}

Index System::numDegreesOfFreedom() const {
  return 3 * (numVertices() + (filaments_ ? filaments_->numBeads() : 0));
}

Eigen::VectorXd System::coordinates() const {
  Eigen::VectorXd x(numDegreesOfFreedom());
  if (filaments_) filaments_->gather(x.data());
  for (const auto& m : membranes_) {
    const auto& p = m->mesh().positions();
    for (std::size_t i = 0; i < p.size(); ++i) x.segment<3>(3 * (m->dofOffset() + i)) = p[i];
  }
  return x;
}

void System::setCoordinates(const Eigen::VectorXd& x) {
  if (filaments_) filaments_->scatter(x.data());
  for (auto& m : membranes_) {
    auto& p = m->mesh().positions();
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = x.segment<3>(3 * (m->dofOffset() + i));
  }
}

}  // namespace cortex
