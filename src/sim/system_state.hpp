// What a System is beyond its Config: the state a checkpoint stores and a resumed
// System starts from. Each struct lists its scalar fields once (fields()), so checkpoint
// writing and reading cannot drift apart.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "chem/chemistry_engine.hpp"
#include "filament/filament_network.hpp"
#include "membrane/membrane.hpp"
#include "mesh/triangle_soup.hpp"

namespace cortex {

struct RunCounters {
  std::int64_t minimizations = 0;
  std::int64_t minimizer_iterations = 0;
  std::int64_t unconverged_minimizations = 0;
  double last_max_force = 0.0;  // pN, after the latest minimization
  double mechanics_seconds = 0.0;
  double force_seconds = 0.0;           // of mechanics_seconds: force evaluations
  double preconditioner_seconds = 0.0;  // of mechanics_seconds: factorizing and applying the Sobolev metric
  std::int64_t preconditioner_factorizations = 0;
  double remesh_seconds = 0.0;
  double chemistry_seconds = 0.0;
  double feedback_seconds = 0.0;  // rates and confinement after each minimization (incl. binding-pair search)

  // f(name, field) for every field.
  template <class Self, class F>
  static void fields(Self& c, F&& f) {
    f("minimizations", c.minimizations);
    f("minimizer_iterations", c.minimizer_iterations);
    f("unconverged_minimizations", c.unconverged_minimizations);
    f("last_max_force", c.last_max_force);
    f("mechanics_seconds", c.mechanics_seconds);
    f("force_seconds", c.force_seconds);
    f("preconditioner_seconds", c.preconditioner_seconds);
    f("preconditioner_factorizations", c.preconditioner_factorizations);
    f("remesh_seconds", c.remesh_seconds);
    f("chemistry_seconds", c.chemistry_seconds);
    f("feedback_seconds", c.feedback_seconds);
  }
};

// The part of a membrane's state that a checkpoint stores.
struct MembraneState {
  TriangleSoup mesh;
  std::vector<char> fixed;
  MembraneMaterial material;
  RemeshStats remesh_totals;
  // The remesher's settings as resolved at the start (a loaded mesh's defaults come from
  // its original edge lengths, which remeshing changes).
  std::optional<RemeshSettings> remeshing;
  // Surface species: names and copies per vertex (Membrane::setSpecies).
  std::vector<std::string> species;
  std::vector<std::vector<int>> species_copies;

  MembraneEquilibrium equilibrium;
  RelaxationMetric metric;

  template <class Self, class F>
  static void fields(Self& s, F&& f) {
    f("initial_area", s.material.initial_area);
    f("initial_volume", s.material.initial_volume);
    f("tension", s.equilibrium.tension);
    f("pressure", s.equilibrium.pressure);
    f("strain_since_remesh", s.equilibrium.strain_since_remesh);
  }
};

// The network's whole state.
struct FilamentState {
  std::vector<Filament> filaments;
  std::vector<Binding> linkers, motors;
  std::vector<Branch> branches;
  FilamentEvents events;
};

struct SystemState {
  double time = 0.0;      // s
  std::int64_t step = 0;  // chemistry windows completed
  std::int64_t force_evaluations = 0, energy_evaluations = 0;  // the force field's counters
  RunCounters counters;
  std::vector<std::string> bodies;  // names, in the order their coordinates are laid out
  std::map<std::string, MembraneState> membranes;
  std::optional<ChemistryState> chemistry;
  std::optional<FilamentState> filaments;

  template <class Self, class F>
  static void fields(Self& s, F&& f) {
    f("time", s.time);
    f("step", s.step);
    f("force_evaluations", s.force_evaluations);
    f("energy_evaluations", s.energy_evaluations);
  }
};

}  // namespace cortex
