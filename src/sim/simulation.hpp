// The simulation loop: windows of (for now) scheduled targets followed by mechanical
// relaxation, with snapshots and checkpoints on a schedule. Output goes through the
// RunObserver interface, so this folder owns no file format.
#pragma once

#include <vector>

#include "mech/minimizer.hpp"
#include "membrane/shape_relaxation.hpp"
#include "sim/run_config.hpp"
#include "sim/system.hpp"

namespace cortex {

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  // Non-const: observables evaluate the energies (the force field counts its evaluations).
  virtual void onSnapshot(System&) {}
  virtual void onCheckpoint(const System&) {}
  virtual void onWindow(const System&, const MinimizationResult&) {}
  // During a relaxation of `what` (a membrane's name, "filaments" or "system"): called
  // every iteration or outer step, so long minimizations can show progress.
  virtual void onRelaxing(const System&, const std::string& /*what*/, const MinimizerProgress&) {}
  // Asked after every window: true stops the run there, after a checkpoint (a signal).
  virtual bool stopRequested() const { return false; }
  // Called now and then within a window (every relaxation progress report, every 2^20
  // chemistry events): may throw RunStopped to abandon a window that a stop request has
  // waited on too long.
  virtual void duringWindow() {}
};

// How run() ended: at end_time, or early at a stop request with a checkpoint written.
enum class RunOutcome { kFinished, kStopped };

class Simulation {
 public:
  Simulation(System& system, const SimulationConfig& simulation, const MinimizerSettings& mechanics,
             RunObserver& observer);
  // A fresh run relaxes the initial state and writes snapshot 0 first; a resumed run
  // continues after system.step.
  RunOutcome run(bool fresh);
  std::int64_t totalWindows() const { return windowsOf(sim_); }
  double timeOfWindow(std::int64_t k) const { return timeOfWindow(sim_, k); }
  // The same for any config: windows of chemistry_window from t = 0, the last one cut at
  // end_time (a checkpoint's clock is checked against them).
  static std::int64_t windowsOf(const SimulationConfig& simulation);
  static double timeOfWindow(const SimulationConfig& simulation, std::int64_t k);

 private:
  // "; not finite where the bodies are: ..." naming the terms whose energy is not finite at
  // the bodies' stored positions, or "" if none.
  std::string nonFiniteTerms();
  MinimizationResult relax();
  // kAuto: membranes one by one (normal displacements, exact constraints, remeshing
  // within), then filaments, in rounds while they push on each other; the rest: all
  // coordinates at once.
  MinimizationResult relaxByBody();
  MinimizationResult relaxMembranes();
  MinimizationResult relaxFilaments();
  MinimizationResult relaxAll();
  void checkMeshes() const;
  // A filament through a membrane is an error (exit 1), named with `when` it was found.
  void checkCrossings(const char* when) const;
  // Two membranes through each other after a relaxation (only relaxations move them) are
  // an error (exit 1): nothing in the model keeps them apart.
  void checkMembranesApart() const;
  // A relaxation that ended far from the tolerance is an error, not a warning.
  void checkRelaxation(const MinimizationResult& r) const;
  // A relaxation that thinned a coat by stretching its cells is an error: the model keeps
  // copies on vertices, not on the lipid (Membrane::coatCoverage, before the relaxation).
  void checkCoats(const std::vector<double>& coverage_before) const;
  void remeshMembranes();
  void advanceChemistry(double t_end);
  bool crosses(double interval, std::int64_t k) const;
  // Reports the relaxation of `what` to the observer.
  MinimizerProgressCallback progressOf(std::string what);

  System& system_;
  SimulationConfig sim_;
  MinimizerSettings mech_;
  RunObserver& observer_;
  // One per membrane, in the System's order: what its relaxations within a window share.
  std::vector<ShapeRelaxationWarmStart> warm_starts_;
};

}  // namespace cortex
