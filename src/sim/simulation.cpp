#include "sim/simulation.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "mesh/mesh_quality.hpp"

namespace cortex {

Simulation::Simulation(System& system, const SimulationConfig& simulation,
                       const MinimizerSettings& mechanics, RunObserver& observer)
    : system_(system), sim_(simulation), mech_(mechanics), observer_(observer) {}

std::int64_t Simulation::totalWindows() const {
  return static_cast<std::int64_t>(std::ceil(sim_.end_time / sim_.chemistry_window - 1e-9));
}

// Times come from the window index, never from accumulated sums, so a resumed run
// sees exactly the same times as an uninterrupted one.
double Simulation::timeOfWindow(std::int64_t k) const {
  return std::min(static_cast<double>(k) * sim_.chemistry_window, sim_.end_time);
}

bool Simulation::crosses(double interval, std::int64_t k) const {
  if (k == totalWindows()) return true;
  auto slot = [&](std::int64_t j) { return std::floor(timeOfWindow(j) / interval + 1e-9); };
  return slot(k) > slot(k - 1);
}

// Below this angle a triangle has collapsed: its normal, curvature and forces are
// meaningless, and continuing would only write nonsense.
constexpr double kCollapsedAngleDeg = 0.1;

void Simulation::checkMeshes() const {
  for (const auto& m : system_.membranes()) {
    // No lipid membrane survives a hundred-fold change of area: the energy is unbounded
    // (e.g. negative tension without area elasticity) even if each minimization stayed
    // within its own bounds.
    const double growth = m->currentGeometry().area / m->material().initial_area;
    if (growth > 100.0 || growth < 0.01)
      throw RunError(fmt::format(
          "membrane \"{}\": area changed {:.3g}-fold since the start at t = {:.6g} s: the energy "
          "is unbounded; check the signs and sizes of tension and moduli",
          m->name(), growth, system_.time()));
    const MeshQuality q = measureQuality(m->mesh());
    if (q.min_angle_deg < kCollapsedAngleDeg)
      throw RunError(fmt::format(
          "membrane \"{}\": triangle {} collapsed (smallest angle {:.3g} deg) at t = {:.6g} s. "
          "Drive the shape change more gently (smaller steps in the schedules), or raise "
          "mesh_regularization",
          m->name(), q.worst_face, q.min_angle_deg, system_.time()));
  }
}

void Simulation::remeshMembranes() {
  bool changed = false;
  for (auto& m : system_.membranes()) {
    if (!m->remeshing()) continue;
    const auto start = std::chrono::steady_clock::now();
    const RemeshStats s = m->remesh(*m->remeshing());
    system_.counters.remesh_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    spdlog::debug("t = {:.6g} s: remeshed \"{}\" in {} sweeps: {} splits, {} collapses, {} flips, {} "
                  "relocations; {} vertices",
                  system_.time(), m->name(), s.sweeps, s.splits, s.collapses, s.flips, s.relocations,
                  m->mesh().numVertices());
    changed = true;
  }
  if (changed) system_.layOut();
}

void Simulation::advanceChemistry(double t_end) {
  ChemistryEngine* chem = system_.chemistry();
  if (!chem) return;
  const auto start = std::chrono::steady_clock::now();
  chem->advance(t_end);
  system_.counters.chemistry_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

MinimizationResult Simulation::relax() {
  // Chemistry may have grown, bound or branched filaments since the last relaxation.
  if (system_.filaments()) system_.layOut();
  MinimizationResult r{true, 0, 0.0, 0.0, "nothing to relax"};
  RunCounters& c = system_.counters;
  if (system_.hasMechanics()) {
    const auto start = std::chrono::steady_clock::now();
    Eigen::VectorXd x = system_.coordinates();
    r = minimize(system_.forceField(), x, mech_);
    system_.setCoordinates(x);
    ++c.minimizations;
    c.minimizer_iterations += r.iterations;
    c.last_max_force = r.max_force;
    c.mechanics_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  remeshMembranes();
  checkMeshes();
  // Membranes and filaments moved: confinement, loads, tensions and binding partners
  // change the rates.
  const auto feedback_start = std::chrono::steady_clock::now();
  system_.updateFeedback();
  c.feedback_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - feedback_start).count();
  if (!r.converged) {
    ++c.unconverged_minimizations;
    spdlog::warn("t = {:.6g} s: minimization stopped before convergence after {} iterations "
                 "(max force {:.3g} pN > tolerance {:.3g} pN): {}",
                 system_.time(), r.iterations, r.max_force, mech_.force_tolerance, r.stop_reason);
  }
  return r;
}

RunOutcome Simulation::run(bool fresh) {
  const double checkpoint_interval =
      sim_.checkpoint_interval > 0 ? sim_.checkpoint_interval : sim_.snapshot_interval;
  if (fresh) {
    system_.step = 0;
    system_.setTime(0.0);
    observer_.onWindow(system_, relax());
    observer_.onSnapshot(system_);
    observer_.onCheckpoint(system_);
    if (observer_.stopRequested()) return RunOutcome::kStopped;
  }
  for (std::int64_t k = system_.step + 1; k <= totalWindows(); ++k) {
    advanceChemistry(timeOfWindow(k));
    system_.setTime(timeOfWindow(k));
    const MinimizationResult r = relax();
    system_.step = k;
    observer_.onWindow(system_, r);
    if (crosses(sim_.snapshot_interval, k)) observer_.onSnapshot(system_);
    const bool checkpointed = crosses(checkpoint_interval, k);
    if (checkpointed) observer_.onCheckpoint(system_);
    // A stop keeps the window just finished: the checkpoint makes the resume continue
    // exactly where an uninterrupted run would.
    if (observer_.stopRequested() && k < totalWindows()) {
      if (!checkpointed) observer_.onCheckpoint(system_);
      return RunOutcome::kStopped;
    }
  }
  return RunOutcome::kFinished;
}

}  // namespace cortex
