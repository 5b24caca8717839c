// Small filament systems for the chemistry tests: a compartment grid, species, a network
// and its reactions, wired into a next-subvolume engine, with the filament terms and the
// mechanochemical feedback of a run but no minimization.
#pragma once

#include <memory>

#include "chem/chemistry_engine.hpp"
#include "core/constants.hpp"
#include "filament/filament_chemistry.hpp"
#include "filament/filament_network.hpp"
#include "filament/filament_terms.hpp"
#include "sim/filament_feedback.hpp"

namespace cortex::filtest {

inline constexpr double kT = constants::kBoltzmann * 298.15;

// Actin with the MEDYAN end rates of docs/benchmarks.md, species 0 its monomer.
inline FilamentType actin() {
  FilamentType t;
  t.monomer_species = "G";
  t.monomer_species_index = 0;
  t.plus_on = 11.6, t.plus_off = 1.4, t.minus_on = 1.3, t.minus_off = 0.8;
  return t;
}

struct Rig {
  CompartmentGrid grid;
  ChemistryModel model;
  std::unique_ptr<FilamentNetwork> network;
  std::unique_ptr<FilamentChemistry> chemistry;
  std::unique_ptr<ChemistryEngine> engine;
  ForceField force_field;
  std::unique_ptr<FilamentFeedback> feedback;

  // One compartment per `shape` entry of edge `size`; species copies all in compartment 0
  // unless `spread`; `build` adds filaments to the network before the engine starts.
  template <class Build>
  Rig(double size, std::array<int, 3> shape, std::vector<SpeciesDef> species, std::vector<int> copies,
      FilamentConfig config, Build&& build, std::uint64_t seed = 7)
      : grid{size, shape} {
    model.volumes = gridGraph(grid);
    model.species = std::move(species);
    network = std::make_unique<FilamentNetwork>(std::move(config));
    build(*network);
    network->setOffset(0);
    chemistry = std::make_unique<FilamentChemistry>(*network, grid, model.species, kT);
    chemistry->addReactions(model);
    std::vector<int> all(static_cast<std::size_t>(grid.count()) * model.species.size(), 0);
    for (std::size_t s = 0; s < copies.size(); ++s) all[s] = copies[s];
    engine = makeChemistryEngine(EngineKind::kNextSubvolume, model, all, seed);
    chemistry->attach(*engine);
    feedback = std::make_unique<FilamentFeedback>(*network, addFilamentTerms(*network, force_field), *chemistry);
    relaxed();
  }

  // What a run does after a relaxation (here of a network that did not move): lay the
  // network out again and feed its forces and tensions back into the rates.
  void relaxed() {
    network->setOffset(0);
    Eigen::VectorXd x(3 * network->numPoints());
    network->gather(x.data());
    feedback->apply(x, force_field);
  }

  int total(Index species) const {
    int n = 0;
    for (Index c = 0; c < grid.count(); ++c) n += engine->copies(c, species);
    return n;
  }
};

}  // namespace cortex::filtest
