#include "chem/reaction_network.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "core/error.hpp"

namespace cortex {

namespace {

void validateGrid(const CompartmentGrid& grid) {
  if (!(grid.size > 0.0) || !std::isfinite(grid.size))
    throw InputError("compartments: size must be a positive number of nm");
  double count = 1.0;
  for (int n : grid.shape) {
    if (n < 1) throw InputError("compartments: every entry of shape must be >= 1");
    count *= n;
  }
  if (count > 2.0e8) throw InputError("compartments: more than 2e8 compartments");
}

// Net change per species, merged (a reactant listed twice counts twice) and in
// ascending species order so that updates run in a fixed order.
std::map<Index, int> netChanges(const ReactionDef& r) {
  std::map<Index, int> net;
  for (const Stoichiometry& s : r.reactants) net[s.species] -= s.count;
  for (const Stoichiometry& s : r.products) net[s.species] += s.count;
  return net;
}

ReactionKernel kernelFor(const ReactionDef& r, double volume, Index num_species) {
  std::map<Index, int> reactants;
  for (const Stoichiometry& s : r.reactants) reactants[s.species] += s.count;
  for (const auto& list : {r.reactants, r.products})
    for (const Stoichiometry& s : list)
      if (s.species < 0 || s.species >= num_species || s.count < 1)
        throw InputError("reaction \"" + r.equation + "\": invalid species index or count");
  if (!std::isfinite(r.rate) || r.rate < 0.0)
    throw InputError("reaction \"" + r.equation + "\": rate must be finite and >= 0");

  ReactionKernel k;
  k.constant = stochasticRateConstant(r, volume);
  switch (r.order()) {
    case 0:
      k.kind = ReactionKernel::Kind::kConstant;
      break;
    case 1:
      k.kind = ReactionKernel::Kind::kLinear;
      k.a = reactants.begin()->first;
      break;
    case 2:
      k.a = reactants.begin()->first;
      if (reactants.size() == 1) {
        k.kind = ReactionKernel::Kind::kDimer;
      } else {
        k.kind = ReactionKernel::Kind::kPair;
        k.b = std::next(reactants.begin())->first;
      }
      break;
    default:
      throw InputError("reaction \"" + r.equation + "\": order " + std::to_string(r.order()) +
                       " is not supported (at most 2)");
  }
  return k;
}

}  // namespace

ReactionNetwork::ReactionNetwork(const ChemistryModel& model) {
  validateGrid(model.grid);
  numSpecies = static_cast<Index>(model.species.size());
  numReactions = static_cast<Index>(model.reactions.size());
  numCompartments = model.grid.count();

  const double h2 = model.grid.size * model.grid.size;
  for (Index s = 0; s < numSpecies; ++s) {
    const double d = model.species[s].diffusion;
    if (!std::isfinite(d) || d < 0.0)
      throw InputError("species \"" + model.species[s].name + "\": diffusion must be finite and >= 0");
    hopRate.push_back(d / h2);
    if (d > 0.0) diffusing.push_back(s);
  }

  std::vector<std::vector<Index>> readers(numSpecies);
  for (Index r = 0; r < numReactions; ++r) {
    const ReactionDef& def = model.reactions[r];
    kernels.push_back(kernelFor(def, model.grid.volume(), numSpecies));
    hooked.push_back(def.hooked ? 1 : 0);
    perSite.push_back(def.per_site ? 1 : 0);
    for (const auto& [s, delta] : netChanges(def))
      if (delta != 0) changes.values.push_back({s, delta});
    changes.endRow();
    const ReactionKernel& k = kernels.back();
    if (k.kind != ReactionKernel::Kind::kConstant) readers[k.a].push_back(r);
    if (k.kind == ReactionKernel::Kind::kPair) readers[k.b].push_back(r);
  }
  for (Index s = 0; s < numSpecies; ++s) {
    dependents.values.insert(dependents.values.end(), readers[s].begin(), readers[s].end());
    dependents.endRow();
  }
  for (Index r = 0; r < numReactions; ++r) {
    std::vector<Index> hit;
    for (const SpeciesChange& c : changes[r])
      hit.insert(hit.end(), readers[c.species].begin(), readers[c.species].end());
    std::sort(hit.begin(), hit.end());
    hit.erase(std::unique(hit.begin(), hit.end()), hit.end());
    affected.values.insert(affected.values.end(), hit.begin(), hit.end());
    affected.endRow();
  }
}

}  // namespace cortex
