// All simulation state in one object, assembled in one place (system.cpp) from a typed
// Config and, when resuming, the stored SystemState: the bodies (membranes, then the
// filament network) laid out in one coordinate vector, the force field of every module's
// terms, the chemistry with every module's reactions, the feedback between them, the
// clock and the counters. Passed explicitly; no globals, no setters whose order matters.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "chem/chemistry_engine.hpp"
#include "filament/boundary_energy.hpp"
#include "filament/filament_chemistry.hpp"
#include "filament/filament_network.hpp"
#include "filament/filament_terms.hpp"
#include "interact/membrane_bead_exclusion.hpp"
#include "filament/excluded_volume_end_loads.hpp"
#include "interact/membrane_end_loads.hpp"
#include "mech/force_field.hpp"
#include "membrane/membrane.hpp"
#include "sim/feedback.hpp"
#include "sim/run_config.hpp"
#include "sim/system_state.hpp"

namespace cortex {

class SurfaceSpeciesFeedback;

class System {
 public:
  // Throws InputError for a config that cannot be built, or a state that does not match it.
  explicit System(const Config& config, const SystemState* restored = nullptr);
  ~System();
  System(const System&) = delete;
  System& operator=(const System&) = delete;

  // The state a checkpoint stores (System(config, &state) continues from it).
  SystemState state() const;

  // --- bodies and mechanics --------------------------------------------------------
  const std::vector<Body*>& bodies() const { return bodies_; }
  std::vector<std::unique_ptr<Membrane>>& membranes() { return membranes_; }
  const std::vector<std::unique_ptr<Membrane>>& membranes() const { return membranes_; }
  FilamentNetwork* filaments() { return filaments_.get(); }
  const FilamentNetwork* filaments() const { return filaments_.get(); }
  ForceField& forceField() { return force_field_; }
  const ForceField& forceField() const { return force_field_; }
  // Recomputes every body's offset and the frozen mask after point counts changed
  // (remeshing, chemistry); terms and the force field's counters stay.
  void layOut();
  // All coordinates as one vector (the minimizer's variables) and back into the bodies.
  Eigen::VectorXd coordinates() const;
  void setCoordinates(const Eigen::VectorXd& x);
  // Terms between membranes and filaments (empty when they do not interact): their
  // bodies are relaxed in turn until both are at rest under them.
  const std::vector<MembraneBeadExclusion*>& couplingTerms() const { return coupling_terms_; }
  Index numVertices() const;  // membrane vertices
  Index numDegreesOfFreedom() const;
  bool hasMechanics() const { return numDegreesOfFreedom() > 0; }

  // --- chemistry ----------------------------------------------------------------------
  ChemistryEngine* chemistry() { return chemistry_.get(); }
  const ChemistryEngine* chemistry() const { return chemistry_.get(); }
  const ChemistryModel& chemistryModel() const { return chemistry_model_; }
  const CompartmentGrid& grid() const { return grid_; }  // the default grid without chemistry
  const FilamentChemistry* filamentChemistry() const { return filament_chemistry_.get(); }

  // After a relaxation: confinement and force-dependent rates follow the new positions.
  void updateFeedback();
  // After a chemistry window: the copies of membrane species go back to the vertices,
  // where remeshing carries them (sim/surface_species.hpp).
  void collectSurfaceCopies();
  // Mesh edges the membrane species' hops left out at the last feedback update, over all
  // membranes: {negative cotangent sum, closed by a linear drift (summed over species)}.
  std::array<Index, 2> closedSurfaceEdges() const;

  // --- clock --------------------------------------------------------------------------
  // Evaluates every scheduled parameter at time t.
  void setTime(double t);
  double time() const { return time_; }
  std::int64_t step = 0;  // chemistry windows completed
  RunCounters counters;

 private:
  void buildChemistry(const Config& config, const SystemState* restored, const FilamentTerms& filament_terms);

  std::vector<std::unique_ptr<Membrane>> membranes_;
  std::unique_ptr<FilamentNetwork> filaments_;
  std::vector<Body*> bodies_;
  ForceField force_field_;
  std::vector<MembraneBeadExclusion*> coupling_terms_;
  // The loads that follow a filament end within a window (filament/end_load_probe.hpp):
  // membranes' (with coupling terms), walls' (with [boundary]), the other cylinders', and
  // their sum.
  std::unique_ptr<MembraneEndLoads> end_loads_;
  std::unique_ptr<WallEndLoads> wall_loads_;
  std::unique_ptr<CylinderExclusionEndLoads> cylinder_loads_;
  std::unique_ptr<EndLoadSum> end_load_sum_;
  CompartmentGrid grid_;
  ChemistryModel chemistry_model_;
  std::unique_ptr<FilamentChemistry> filament_chemistry_;
  std::unique_ptr<ChemistryEngine> chemistry_;
  std::vector<std::unique_ptr<Feedback>> feedback_;  // in the order they run
  SurfaceSpeciesFeedback* surface_species_ = nullptr;  // one of feedback_, with membrane species
  double time_ = 0.0;
};

}  // namespace cortex
