// All simulation state in one object: the membranes, the force field over their
// coordinates, the clock and the counters. Passed explicitly; no globals.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "chem/chemistry_engine.hpp"
#include "filament/filament_chemistry.hpp"
#include "filament/filament_network.hpp"
#include "mech/force_field.hpp"
#include "sim/run_config.hpp"
#include "membrane/membrane.hpp"

namespace cortex {

struct RunCounters {
  std::int64_t minimizations = 0;
  std::int64_t minimizer_iterations = 0;
  std::int64_t unconverged_minimizations = 0;
  double last_max_force = 0.0;  // pN, after the latest minimization
  double mechanics_seconds = 0.0;
  double remesh_seconds = 0.0;
  double chemistry_seconds = 0.0;
  double feedback_seconds = 0.0;  // filament rates after each minimization (incl. binding-pair search)
};

class System {
 public:
  // Takes ownership of the membranes, lays out their coordinates and builds the force field.
  explicit System(std::vector<std::unique_ptr<Membrane>> membranes);

  // 3D reaction-diffusion, if the config has species; `sides` per species (may be empty:
  // nothing confined).
  void setChemistry(ChemistryModel model, std::unique_ptr<ChemistryEngine> engine,
                    std::vector<SpeciesSide> sides = {}) {
    chemistry_model_ = std::move(model);
    chemistry_ = std::move(engine);
    species_sides_ = std::move(sides);
  }
  const std::vector<SpeciesSide>& speciesSides() const { return species_sides_; }
  // Per reaction: where it may fire (run_config.hpp); applied with the confinement.
  void setReactionRestrictions(std::vector<ReactionRestriction> r) { reaction_restrictions_ = std::move(r); }
  const std::vector<ReactionRestriction>& reactionRestrictions() const { return reaction_restrictions_; }
  ChemistryEngine* chemistry() { return chemistry_.get(); }
  const ChemistryEngine* chemistry() const { return chemistry_.get(); }
  const ChemistryModel& chemistryModel() const { return chemistry_model_; }

  // The cytoskeleton: adds the filament energy terms to the force field. Its chemistry
  // (if any) is hooked into the engine by setFilamentChemistry.
  void setFilaments(std::unique_ptr<FilamentNetwork> network);
  void setFilamentChemistry(std::unique_ptr<FilamentChemistry> chemistry);
  FilamentNetwork* filaments() { return filaments_.get(); }
  const FilamentNetwork* filaments() const { return filaments_.get(); }
  FilamentChemistry* filamentChemistry() { return filament_chemistry_.get(); }
  const FilamentChemistry* filamentChemistry() const { return filament_chemistry_.get(); }
  // After a minimization: force-dependent filament rates (mechanochemical feedback).
  void updateMechanochemistry();

  std::vector<std::unique_ptr<Membrane>>& membranes() { return membranes_; }
  const std::vector<std::unique_ptr<Membrane>>& membranes() const { return membranes_; }
  ForceField& forceField() { return force_field_; }
  const ForceField& forceField() const { return force_field_; }

  // Recomputes coordinate offsets, the filament layout and the frozen mask after vertex or
  // bead counts changed (remeshing, chemistry); the energy terms and the force field's
  // counters stay.
  void layOut();

  // Evaluates every scheduled parameter at time t.
  void setTime(double t);
  double time() const { return time_; }
  std::int64_t step = 0;  // chemistry windows completed
  RunCounters counters;

  // All coordinates as one vector (the minimizer's variables) and back into the meshes.
  Eigen::VectorXd coordinates() const;
  void setCoordinates(const Eigen::VectorXd& x);
  Index numVertices() const;  // membrane vertices
  Index numDegreesOfFreedom() const;  // 3 * (vertices + filament beads)
  bool hasMechanics() const { return !membranes_.empty() || (filaments_ && !filaments_->filaments().empty()); }

 private:
  void buildForceField();

  std::vector<std::unique_ptr<Membrane>> membranes_;
  ForceField force_field_;
  ChemistryModel chemistry_model_;
  std::unique_ptr<ChemistryEngine> chemistry_;
  std::vector<SpeciesSide> species_sides_;
  std::vector<ReactionRestriction> reaction_restrictions_;
  std::unique_ptr<FilamentNetwork> filaments_;
  std::unique_ptr<FilamentChemistry> filament_chemistry_;
  double time_ = 0.0;
};

}  // namespace cortex
