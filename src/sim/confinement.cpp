#include "sim/confinement.hpp"

#include <fmt/format.h>

#include <map>

#include "chem/compartment_slicing.hpp"
#include "core/error.hpp"

namespace cortex {

std::vector<std::optional<SideFractions>> speciesFractions(const System& system, const std::vector<SpeciesSide>& sides,
                                                           const CompartmentGrid& grid) {
  std::vector<std::optional<SideFractions>> out(sides.size());
  std::map<std::string, CompartmentSlices> slices;
  for (std::size_t s = 0; s < sides.size(); ++s) {
    const SpeciesSide& side = sides[s];
    if (side.membrane.empty()) continue;
    auto it = slices.find(side.membrane);
    if (it == slices.end()) {
      const Membrane* m = nullptr;
      for (const auto& candidate : system.membranes())
        if (candidate->name() == side.membrane) m = candidate.get();
      const char* key = side.outside ? "outside" : "inside";
      if (!m) throw InputError(fmt::format("[[species]] {}: no membrane is named \"{}\"", key, side.membrane));
      if (!m->isClosed())
        throw InputError(fmt::format("[[species]] {}: membrane \"{}\" is open and confines nothing", key, side.membrane));
      it = slices.emplace(side.membrane, sliceCompartments(m->mesh().positions(), m->mesh().triangles(), grid)).first;
    }
    const CompartmentSlices& cut = it->second;
    SideFractions f{cut.volume, cut.faces};
    if (side.outside) {
      for (double& v : f.volume) v = 1.0 - v;
      for (auto& face : f.faces)
        for (double& a : face) a = 1.0 - a;
    }
    out[s] = std::move(f);
  }
  return out;
}

void confineChemistry(System& system) {
  ChemistryEngine* engine = system.chemistry();
  if (!engine) return;
  const auto fractions = speciesFractions(system, system.speciesSides(), system.chemistryModel().grid);
  for (std::size_t s = 0; s < fractions.size(); ++s)
    if (fractions[s]) engine->setConfinement(static_cast<Index>(s), fractions[s]->volume, fractions[s]->faces);
}

}  // namespace cortex
