#include "io/system_builder.hpp"

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "sim/chemistry_builder.hpp"
#include "sim/confinement.hpp"
#include "sim/filament_builder.hpp"
#include "sim/membrane_builder.hpp"

namespace cortex {

std::unique_ptr<System> buildSystem(const Config& config, const Checkpoint* restored) {
  std::vector<std::unique_ptr<Membrane>> membranes;
  for (const MembraneConfig& mc : config.membranes) {
    std::optional<MembraneState> state;
    if (restored) {
      auto it = restored->membranes.find(mc.name);
      if (it == restored->membranes.end())
        throw InputError(fmt::format("checkpoint has no membrane \"{}\"", mc.name));
      state = it->second;
    }
    membranes.push_back(buildMembrane(mc, config.source, state));
  }
  auto system = std::make_unique<System>(std::move(membranes));
  const auto seed = static_cast<std::uint64_t>(config.simulation.seed);
  // Filament reactions extend the config's reaction network (after its own reactions).
  std::optional<ChemistryConfig> chemistry = config.chemistry;
  std::unique_ptr<FilamentChemistry> filament_chemistry;
  if (config.filaments) {
    if (restored && !restored->filaments) throw InputError("checkpoint has no filaments, the config has");
    // Without chemistry the grid is the default one (no [compartments] without species).
    const CompartmentGrid g = chemistry ? chemistry->model.grid : CompartmentGrid{};
    const Vec3 box_min = Vec3::Zero(), box_max = g.extent();
    std::unique_ptr<FilamentNetwork> network;
    try {
      network = buildFilamentNetwork(*config.filaments, box_min, box_max, seed,
                                     restored ? &*restored->filaments : nullptr);
    } catch (const InputError& e) {
      // Placement names the [[filaments]] table; say which file it is in.
      if (restored) throw;
      throw InputError(fmt::format("{}: {}", config.source, e.what()));
    }
    if (chemistry) {
      filament_chemistry = std::make_unique<FilamentChemistry>(
          *network, chemistry->model, constants::kBoltzmann * config.simulation.temperature);
      filament_chemistry->addReactions(chemistry->model);
    }
    system->setFilaments(std::move(network));
  }
  if (chemistry) {
    if (restored && restored->chemistry) {
      const ChemistryState& s = *restored->chemistry;
      const std::size_t expected =
          static_cast<std::size_t>(chemistry->model.grid.count()) * chemistry->model.species.size();
      if (s.copies.size() != expected || s.reaction_events.size() != chemistry->model.reactions.size())
        throw InputError("checkpoint chemistry does not match the config (grid, species or reactions changed)");
      auto engine = makeChemistryEngine(chemistry->engine, chemistry->model, s.copies, seed);
      RandomStream random(seed, StreamId::kChemistry);
      random.restore(s.random_counter, s.random_used);
      engine->restore(random, s.time, s.events, s.reaction_events, s.diffusion_events);
      system->setChemistry(chemistry->model, std::move(engine), chemistry->sides);
    } else {
      // Confined species start uniform in the volume on their side of the membrane.
      std::vector<std::vector<double>> weights(chemistry->sides.size());
      const auto fractions = speciesFractions(*system, chemistry->sides, chemistry->model.grid);
      for (std::size_t s = 0; s < fractions.size(); ++s)
        if (fractions[s]) weights[s] = fractions[s]->volume;
      system->setChemistry(chemistry->model, buildChemistry(*chemistry, seed, weights), chemistry->sides);
    }
    // The membranes as built or restored decide the confinement, and the config the
    // reaction restrictions: nothing is stored for either.
    system->setReactionRestrictions(chemistry->reaction_restrictions);
    confineChemistry(*system);
    if (filament_chemistry) {
      system->setFilamentChemistry(std::move(filament_chemistry));
      // Likewise the force-dependent filament rates follow from the stored positions.
      system->updateMechanochemistry();
    }
  }
  return system;
}

}  // namespace cortex
