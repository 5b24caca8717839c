#include "io/chemistry_config.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"

namespace cortex {
namespace {

CompartmentGrid readGrid(const ConfigReader& r) {
  CompartmentGrid g;
  g.size = r.number("size", g.size, Range::positive(), "nm");
  if (r.has("shape")) {
    const auto s = r.numbers("shape", 3, Range{1.0, 1e6}, "compartments");
    for (int k = 0; k < 3; ++k) {
      if (s[k] != std::floor(s[k])) r.fail("shape", "entries must be whole numbers");
      g.shape[k] = static_cast<int>(s[k]);
    }
  }
  if (static_cast<double>(g.shape[0]) * g.shape[1] * g.shape[2] > 1e8)
    r.fail("shape", "more than 1e8 compartments");
  r.finish();
  return g;
}

SpeciesConfig readSpecies(const ConfigReader& r, double box_volume_nm3) {
  SpeciesConfig s;
  s.def.name = r.string("name", "");
  if (s.def.name.empty() || s.def.name.find_first_of(" \t/+>") != std::string::npos)
    r.fail("name", "must be a non-empty name without spaces, '/', '+' or '>'");
  s.def.diffusion = r.number("diffusion", 0.0, Range::nonNegative(), "nm^2/s");
  for (const char* k : {"inside", "outside"})
    if (r.has(k)) r.fail(k, "confinement by membranes is not supported yet in this version");
  const bool by_copies = r.has("copies"), by_concentration = r.has("concentration");
  if (by_copies && by_concentration) r.fail("concentration", "give either copies or concentration, not both");
  if (by_copies) s.copies = r.integer("copies", 0, 0, 2'000'000'000);
  if (by_concentration) {
    const double c = r.requiredNumber("concentration", Range::nonNegative(), "µM");
    s.copies = std::llround(c * kCopiesPerMicromolarFemtoliter * box_volume_nm3 * 1e-9);
    if (s.copies > 2'000'000'000) r.fail("concentration", "gives more than 2e9 copies in the box");
  }
  r.finish();
  return s;
}

}  // namespace

std::optional<ChemistryConfig> readChemistry(const ConfigReader& root) {
  const auto species = root.tableArray("species");
  if (species.empty()) {
    for (const char* k : {"reaction", "compartments", "chemistry"})
      if (root.has(k)) root.fail(k, "has no effect without [[species]]");
    return std::nullopt;
  }
  ChemistryConfig c;
  if (auto g = root.table("compartments")) c.model.grid = readGrid(*g);
  if (auto e = root.table("chemistry")) {
    c.engine = e->choice("engine", "nsm", {"nsm", "direct"}) == "direct" ? EngineKind::kDirect
                                                                         : EngineKind::kNextSubvolume;
    e->finish();
  }
  const double box = c.model.grid.volume() * c.model.grid.count();
  for (std::size_t i = 0; i < species.size(); ++i) {
    SpeciesConfig s = readSpecies(species[i], box);
    for (const SpeciesDef& other : c.model.species)
      if (other.name == s.def.name) species[i].fail("name", fmt::format("\"{}\" is declared twice", s.def.name));
    c.model.species.push_back(s.def);
    c.initial_copies.push_back(s.copies);
  }
  for (const ConfigReader& r : root.tableArray("reaction")) {
    const std::string equation = r.string("equation", "");
    const double rate = r.requiredNumber("rate", Range::nonNegative(), "(1/s, 1/(µM s) or µM/s by order)");
    if (r.has("region")) r.fail("region", "restricting reactions to regions is not supported yet in this version");
    try {
      c.model.reactions.push_back(parseReaction(equation, rate, c.model.species));
    } catch (const InputError& e) {
      r.fail("equation", e.what());
    }
    r.finish();
  }
  return c;
}

}  // namespace cortex
