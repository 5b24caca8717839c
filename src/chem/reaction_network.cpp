#include "chem/reaction_network.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

#include "core/error.hpp"

namespace cortex {

namespace {

// Net change per species, merged (a reactant listed twice counts twice) and in
// ascending species order so that updates run in a fixed order.
std::map<Index, int> netChanges(const ReactionDef& r) {
  std::map<Index, int> net;
  for (const Stoichiometry& s : r.reactants) net[s.species] -= s.count;
  for (const Stoichiometry& s : r.products) net[s.species] += s.count;
  return net;
}

// Where r fires: the surface of its surface species (all on one), else the 3D space.
Index homeRegion(const ReactionDef& r, const std::vector<Index>& species_region) {
  Index home = 0;
  for (const auto& list : {r.reactants, r.products})
    for (const Stoichiometry& s : list) {
      const Index region = species_region[s.species];
      if (region == 0) continue;
      if (home != 0 && home != region)
        throw InputError("reaction \"" + r.equation + "\": its surface species live on different membranes");
      home = region;
    }
  return home;
}

ReactionKernel kernelFor(const ReactionDef& r, Index num_species, const std::vector<Index>& species_region,
                         Index home) {
  std::map<Index, int> reactants;
  for (const Stoichiometry& s : r.reactants) reactants[s.species] += s.count;
  for (const auto& list : {r.reactants, r.products})
    for (const Stoichiometry& s : list)
      if (s.species < 0 || s.species >= num_species || s.count < 1)
        throw InputError("reaction \"" + r.equation + "\": invalid species index or count");
  if (!std::isfinite(r.rate) || r.rate < 0.0)
    throw InputError("reaction \"" + r.equation + "\": rate must be finite and >= 0");
  if (r.per_site && home != 0) throw InputError("reaction \"" + r.equation + "\": per-site reactions are 3D only");

  const auto held = [&](Index s) { return home != 0 && species_region[s] == 0; };
  ReactionKernel k;
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
  k.a_held = k.kind != ReactionKernel::Kind::kConstant && held(k.a);
  k.b_held = k.kind == ReactionKernel::Kind::kPair && held(k.b);
  return k;
}

}  // namespace

ReactionNetwork::ReactionNetwork(const ChemistryModel& model) {
  validate(model.volumes, "chemistry: the 3D subvolumes");
  numSpecies = static_cast<Index>(model.species.size());
  numReactions = static_cast<Index>(model.reactions.size());
  const auto surfaces = static_cast<Index>(model.surfaces.size());
  for (const SpeciesDef& s : model.species) {
    if (!std::isfinite(s.diffusion) || s.diffusion < 0.0)
      throw InputError("species \"" + s.name + "\": diffusion must be finite and >= 0");
    if (s.surface < -1 || s.surface >= surfaces)
      throw InputError("species \"" + s.name + "\": no surface " + std::to_string(s.surface));
    speciesRegion.push_back(s.surface + 1);
  }
  Index covered = 0;
  for (const ReactionRange& range : model.ranges) {
    if (range.begin != covered || range.end < range.begin)
      throw InputError("chemistry: reaction ranges must cover the reactions in order");
    covered = range.end;
  }
  if (covered != numReactions) throw InputError("chemistry: reactions without an owner");

  std::vector<std::vector<Index>> readers(numSpecies), held_readers(numSpecies);
  surface_order_.assign(numReactions, 0);
  held_order_.assign(numReactions, 0);
  for (Index r = 0; r < numReactions; ++r) {
    const ReactionDef& def = model.reactions[r];
    const Index home = homeRegion(def, speciesRegion);
    region.push_back(home);
    kernels.push_back(kernelFor(def, numSpecies, speciesRegion, home));
    order.push_back(def.order());
    perSite.push_back(def.per_site ? 1 : 0);
    rate_.push_back(def.rate);
    sideSpecies.push_back(!def.reactants.empty()  ? def.reactants.front().species
                          : !def.products.empty() ? def.products.front().species
                                                  : -1);
    for (const Stoichiometry& s : def.reactants)
      (speciesRegion[s.species] == 0 && home != 0 ? held_order_ : surface_order_)[r] += s.count;
    for (const auto& [s, delta] : netChanges(def))
      if (delta != 0) changes.values.push_back({s, delta, home != 0 && speciesRegion[s] == 0});
    changes.endRow();
    const ReactionKernel& k = kernels.back();
    // A surface reaction reading only its holder's copies is carried by the holder.
    aggregated.push_back(home != 0 && k.kind != ReactionKernel::Kind::kConstant && surface_order_[r] == 0);
    auto& held_list = aggregated.back() ? readers : held_readers;
    if (k.kind != ReactionKernel::Kind::kConstant) (k.a_held ? held_list : readers)[k.a].push_back(r);
    if (k.kind == ReactionKernel::Kind::kPair) (k.b_held ? held_list : readers)[k.b].push_back(r);
  }
  for (Index s = 0; s < numSpecies; ++s) {
    dependents.values.insert(dependents.values.end(), readers[s].begin(), readers[s].end());
    dependents.endRow();
    heldReaders.values.insert(heldReaders.values.end(), held_readers[s].begin(), held_readers[s].end());
    heldReaders.endRow();
  }
  for (Index r = 0; r < numReactions; ++r) {
    std::vector<Index> hit;
    for (const SpeciesChange& c : changes[r])
      if (!c.held) hit.insert(hit.end(), readers[c.species].begin(), readers[c.species].end());
    std::sort(hit.begin(), hit.end());
    hit.erase(std::unique(hit.begin(), hit.end()), hit.end());
    affected.values.insert(affected.values.end(), hit.begin(), hit.end());
    affected.endRow();
  }
}

namespace {
// x^n for the whole exponents of mass action (a few reactant copies) by products: pow()
// costs some twenty times more, and binding draws evaluate this for every vertex a
// compartment holds (a third of curvature_sorting's wall time went to pow).
double wholePower(double x, int n) {
  double p = 1.0;
  for (int k = 0; k < std::abs(n); ++k) p *= x;
  return n < 0 ? 1.0 / p : p;
}
}  // namespace

double ReactionNetwork::constant(Index r, double size, double holder_volume) const {
  if (region[r] == 0) return stochasticRateConstant(rate_[r], order[r], size);
  // k A prod [M] prod [C]: A^(1 - m) V^(-c).
  return rate_[r] * wholePower(size, 1 - surface_order_[r]) / wholePower(holder_volume, held_order_[r]);
}

}  // namespace cortex
