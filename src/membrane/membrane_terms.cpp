#include "membrane/membrane_terms.hpp"

#include "membrane/area_energy.hpp"
#include "membrane/bending_energy.hpp"
#include "membrane/regularization_energy.hpp"
#include "membrane/volume_energy.hpp"

namespace cortex {

void addMembraneTerms(Membrane& m, ForceField& ff) {
  const MembraneMechanics& p = m.mechanics();
  if (!p.bending.modulus.isZero()) ff.add(std::make_unique<BendingEnergy>(m, p.bending));
  if (!p.area.modulus.isZero() && p.area.model == AreaModel::kPerVertex)
    ff.add(std::make_unique<PerVertexAreaEnergy>(m, p.area));
  if (!p.area.modulus.isZero() && p.area.model == AreaModel::kGlobal)
    ff.add(std::make_unique<GlobalAreaEnergy>(m, p.area));
  if (!p.tension.tension.isZero()) ff.add(std::make_unique<TensionEnergy>(m, p.tension));
  if (!p.regularization.strength.isZero()) ff.add(std::make_unique<RegularizationEnergy>(m, p.regularization));
  // Open membranes refuse volume parameters (Membrane's constructor).
  if (!p.volume.modulus.isZero()) ff.add(std::make_unique<VolumeEnergy>(m, p.volume));
}

}  // namespace cortex
