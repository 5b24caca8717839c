#include "sim/system.hpp"

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

void System::layOut() {
  Index offset = 0;
  std::vector<char> frozen;
  for (auto& m : membranes_) {
    m->setDofOffset(offset);
    offset += m->mesh().numVertices();
    for (char f : m->fixedVertices()) frozen.insert(frozen.end(), 3, f);
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

Eigen::VectorXd System::coordinates() const {
  Eigen::VectorXd x(3 * numVertices());
  for (const auto& m : membranes_) {
    const auto& p = m->mesh().positions();
    for (std::size_t i = 0; i < p.size(); ++i) x.segment<3>(3 * (m->dofOffset() + i)) = p[i];
  }
  return x;
}

void System::setCoordinates(const Eigen::VectorXd& x) {
  for (auto& m : membranes_) {
    auto& p = m->mesh().positions();
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = x.segment<3>(3 * (m->dofOffset() + i));
  }
}

}  // namespace cortex
