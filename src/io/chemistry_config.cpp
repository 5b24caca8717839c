#include "io/chemistry_config.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "core/error.hpp"
#include "io/box_region_config.hpp"
#include "io/membrane_reference.hpp"

namespace cortex {
namespace {

CompartmentGrid readGrid(const ConfigReader& r) {
  CompartmentGrid g;
  // From 1 nm to 1 cm: beyond, hop rates D/h^2 or volumes overflow into inf or 0.
  g.size = r.number("size", g.size, Range{1.0, 1e7}, "nm");
  if (r.has("shape")) {
    const auto s = r.numbers("shape", 3, Range{1.0, 1e6}, "compartments");
    for (int k = 0; k < 3; ++k) {
      if (s[k] != std::floor(s[k])) r.fail("shape", "entries must be whole numbers");
      g.shape[k] = static_cast<int>(s[k]);
    }
  }
  // A compartment costs ~350 bytes with chemistry alone, ~900 with a membrane's slicing
  // and surface species: 1e7 of them take 3.5-9 GB and half a minute to set up (1e8 did not
  // finish, `cortex check` included).
  const double compartments = static_cast<double>(g.shape[0]) * g.shape[1] * g.shape[2];
  if (compartments > 1e7)
    r.fail("shape", fmt::format("{:.3g} compartments, more than 1e7 (~350-900 bytes each in memory)", compartments));
  r.finish();
  return g;
}

// `inside = "NAME"` or `outside = "NAME"`: a side of a closed membrane (or none).
SpeciesSide readSide(const ConfigReader& r, const std::vector<MembraneConfig>& membranes) {
  SpeciesSide side;
  for (const char* k : {"inside", "outside"}) {
    if (!r.has(k)) continue;
    if (!side.membrane.empty()) r.fail(k, "give either inside or outside, not both");
    side.membrane = readClosedMembraneName(r, k, membranes);
    side.outside = std::string(k) == "outside";
  }
  return side;
}

// Initial amount of a 3D species: copies in the whole box (or, when confined, in the
// volume on its side of the membrane), spread uniformly at random in that volume.
struct SpeciesConfig {
  SpeciesDef def;
  std::int64_t copies = 0;
  SpeciesSide side;
};

SpeciesConfig readSpecies(const ConfigReader& r, double box_volume_nm3, const std::vector<MembraneConfig>& membranes) {
  SpeciesConfig s;
  if (!r.has("name")) r.fail("name", "is required");
  s.def.name = r.name("name", "");
  s.def.diffusion = r.number("diffusion", 0.0, Range::nonNegative(), "nm^2/s");
  s.side = readSide(r, membranes);
  const bool by_copies = r.has("copies"), by_concentration = r.has("concentration");
  if (by_copies && by_concentration) r.fail("concentration", "give either copies or concentration, not both");
  // A concentration would need the confined volume, known only once the membrane is built.
  if (by_concentration && !s.side.membrane.empty())
    r.fail("concentration", "give copies for a species confined by a membrane");
  if (by_copies) s.copies = r.integer("copies", 0, 0, 2'000'000'000);
  if (by_concentration) {
    const double c = r.requiredNumber("concentration", Range::nonNegative(), "µM");
    const double copies = c * copiesPerMicromolar(box_volume_nm3);
    if (!(copies <= 2e9)) r.fail("concentration", fmt::format("gives {:.3g} copies in the box, more than 2e9", copies));
    s.copies = std::llround(copies);
  }
  r.finish();
  return s;
}

std::optional<BoxRegion> readRegion(const ConfigReader& reaction, const CompartmentGrid& grid) {
  const std::optional<BoxRegion> box = readBoxRegion(reaction, "region");
  if (!box) return box;
  for (Index c = 0; c < grid.count(); ++c)
    if (box->contains(grid.centre(c))) return box;
  reaction.fail("region", "contains no compartment centre: the reaction could never fire");
}

// The species of every [[membrane.species]], after the 3D ones: surface k is the k-th
// membrane that has species.
void addSurfaceSpecies(ChemistryConfig& c, const ConfigReader& root, const std::vector<MembraneConfig>& membranes) {
  const std::vector<ConfigReader> membrane_tables = root.tableArray("membrane");
  for (std::size_t i = 0; i < membranes.size(); ++i) {
    const MembraneConfig& m = membranes[i];
    if (m.species.empty()) continue;
    const auto surface = static_cast<Index>(c.surfaces.size());
    c.surfaces.push_back(m.name);
    // membranes[i] and its species were read from these tables, in this order: a clash
    // is told at the species' own name key.
    const std::vector<ConfigReader> species_tables = membrane_tables[i].tableArray("species");
    for (std::size_t k = 0; k < m.species.size(); ++k) {
      const SurfaceSpeciesConfig& s = m.species[k];
      for (const SpeciesDef& other : c.species)
        if (other.name == s.name)
          species_tables[k].fail("name",
                  fmt::format("species \"{}\" of membrane \"{}\" has the name of another species; species names "
                              "must be unique across [[species]] and every membrane",
                              s.name, m.name));
      c.species.push_back(SpeciesDef{s.name, s.diffusion, surface, s.footprint});
      c.initial_copies.push_back(0);
      c.sides.emplace_back();
    }
  }
}

// Whether reaction `def` takes copies of surface species `species` off the surface (it
// makes no surface species) in any way but one copy into 3D species only.
bool desorbsSeveral(const ReactionDef& def, Index species, const std::vector<SpeciesDef>& all) {
  std::map<Index, int> net;  // surface species' net changes
  for (const Stoichiometry& x : def.reactants)
    if (all[x.species].surface >= 0) net[x.species] -= x.count;
  for (const Stoichiometry& x : def.products)
    if (all[x.species].surface >= 0) net[x.species] += x.count;
  // A surface product makes it a reaction on the membrane (mass action); without one,
  // the copies taken off leave it.
  for (const auto& [other, change] : net)
    if (change > 0) return false;
  if (!(net[species] < 0)) return false;
  const bool one = def.reactants.size() == 1 && def.reactants.front().count == 1;
  return !one;
}

bool interacting(const std::vector<MembraneConfig>& membranes, const std::string& species) {
  for (const MembraneConfig& m : membranes)
    for (std::size_t j = 0; j < m.species.size(); ++j)
      if (m.species[j].name == species) return copyDependentEnergy(m.species, j);
  return false;
}

}  // namespace

std::optional<ChemistryConfig> readChemistry(const ConfigReader& root, const std::vector<MembraneConfig>& membranes) {
  const auto species = root.tableArray("species");
  bool surface_species = false;
  for (const MembraneConfig& m : membranes) surface_species = surface_species || !m.species.empty();
  if (species.empty() && !surface_species) {
    for (const char* k : {"reaction", "compartments", "chemistry"})
      if (root.has(k)) root.fail(k, "has no effect without [[species]] or [[membrane.species]]");
    return std::nullopt;
  }
  ChemistryConfig c;
  if (auto g = root.table("compartments")) c.grid = readGrid(*g);
  if (auto e = root.table("chemistry")) {
    c.engine = e->choice("engine", "nsm", {"nsm", "direct"}) == "direct" ? EngineKind::kDirect
                                                                         : EngineKind::kNextSubvolume;
    c.max_events_per_window = e->number("max_events_per_window", c.max_events_per_window, Range{1.0, 1e15}, "events");
    e->finish();
  }
  const double box = c.grid.volume() * c.grid.count();
  for (std::size_t i = 0; i < species.size(); ++i) {
    SpeciesConfig s = readSpecies(species[i], box, membranes);
    for (const SpeciesDef& other : c.species)
      if (other.name == s.def.name) species[i].fail("name", fmt::format("\"{}\" is declared twice", s.def.name));
    c.species.push_back(s.def);
    c.initial_copies.push_back(s.copies);
    c.sides.push_back(s.side);
  }
  addSurfaceSpecies(c, root, membranes);
  for (const ConfigReader& r : root.tableArray("reaction")) {
    const std::string equation = r.string("equation", "");
    const double rate = r.requiredNumber("rate", Range::nonNegative(), "(1/s, 1/(µM s) or µM/s by order)");
    ReactionRestriction restriction{readRegion(r, c.grid), readSide(r, membranes)};
    try {
      c.reactions.push_back(parseReaction(equation, rate, c.species));
    } catch (const InputError& e) {
      r.fail("equation", e.what());
    }
    // Confinement scales a propensity by one volume fraction, so a reaction cannot mix
    // 3D species confined to different sides. A reaction with surface species fires on
    // their membrane, and its 3D species react with the compartment holding each vertex.
    const ReactionDef& def = c.reactions.back();
    std::vector<Index> involved;
    Index surface = -1;
    for (const auto* list : {&def.reactants, &def.products})
      for (const Stoichiometry& x : *list) {
        const Index on = c.species[x.species].surface;
        if (on < 0) involved.push_back(x.species);
        if (on >= 0 && surface >= 0 && on != surface)
          r.fail("equation", fmt::format("its species live on different membranes (\"{}\" and \"{}\")",
                                         c.surfaces[surface], c.surfaces[on]));
        if (on >= 0) surface = on;
      }
    // Copies of a species with a pair interaction or curvature sensing leave the surface
    // one at a time, each with the energy it had (ChemistryEngine::SurfaceInteraction).
    for (const Stoichiometry& x : def.reactants)
      if (interacting(membranes, c.species[x.species].name) && desorbsSeveral(def, x.species, c.species))
        r.fail("equation", fmt::format("membrane species \"{}\" has a copy-dependent energy (interaction, "
                                       "cross_interaction or curvature): it may leave "
                                       "the membrane only one copy at a time (\"{} -> C\"), since each copy "
                                       "unbinds with its own energy", c.species[x.species].name,
                                       c.species[x.species].name));
    const bool on_surface = surface >= 0;
    if (on_surface && restriction.restricted())
      r.fail(restriction.region ? "region" : restriction.side.outside ? "outside" : "inside",
             "a reaction of membrane species fires on its membrane; it takes no region or side");
    for (Index sp : involved)
      if (!(c.sides[sp] == c.sides[involved.front()]))
        r.fail("equation", fmt::format("species \"{}\" and \"{}\" are confined to different sides of membranes; "
                                       "a reaction needs all its species on one side",
                                       c.species[involved.front()].name, c.species[sp].name));
    if (!restriction.side.membrane.empty())
      for (Index sp : involved)
        if (!c.sides[sp].membrane.empty())
          r.fail(restriction.side.outside ? "outside" : "inside",
                 fmt::format("species \"{}\" is confined already and the reaction follows it; restrict "
                             "reactions of unconfined species only", c.species[sp].name));
    c.reaction_restrictions.push_back(std::move(restriction));
    r.finish();
  }
  return c;
}

}  // namespace cortex
