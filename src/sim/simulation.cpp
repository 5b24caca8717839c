#include "sim/simulation.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "filament/filament_preconditioner.hpp"
#include "interact/membrane_crossing.hpp"
#include "membrane/shape_relaxation.hpp"
#include "mesh/mesh_quality.hpp"

namespace cortex {

Simulation::Simulation(System& system, const SimulationConfig& simulation,
                       const MinimizerSettings& mechanics, RunObserver& observer)
    : system_(system), sim_(simulation), mech_(mechanics), observer_(observer),
      warm_starts_(system.membranes().size()) {
  // Exact area and volume are constraints of the shape relaxation; the other minimizers
  // would silently drop them.
  if (mech_.kind != MinimizerKind::kAuto)
    for (const auto& m : system_.membranes())
      if (m->mechanics().area.model == AreaModel::kExact || m->mechanics().volume.exact)
        throw InputError(fmt::format("membrane \"{}\": an exact area or volume needs minimizer = \"auto\"", m->name()));
  // A tolerance far above a membrane's own force scale stops its relaxation short of the
  // minimum (naturalForceTolerance); said once, at the start. Under "cg"/"lbfgs" the
  // default 0.1 pN applies to membranes too (a vesicle at v = 0.85 stopped 3.4% above its
  // minimum energy, reported converged).
  const bool by_shape = mech_.kind == MinimizerKind::kAuto;
  if (!by_shape || mech_.force_tolerance_given)
    for (const auto& m : system_.membranes())
      if (const double own = naturalForceTolerance(*m, system_.time()); mech_.force_tolerance > 100.0 * own)
        spdlog::warn("membrane \"{}\": force_tolerance = {:g} pN{} is {:.0f} x its own force scale ({:.2g} pN{}): "
                     "relaxations may stop well short of the minimum{}",
                     m->name(), mech_.force_tolerance, mech_.force_tolerance_given ? "" : " (the default)",
                     mech_.force_tolerance / own, own,
                     by_shape ? ", the default when force_tolerance is not given" : "",
                     by_shape ? "" : "; give a smaller force_tolerance, or use minimizer = \"auto\"");
}

std::int64_t Simulation::windowsOf(const SimulationConfig& simulation) {
  return static_cast<std::int64_t>(std::ceil(simulation.end_time / simulation.chemistry_window - 1e-9));
}

// Times come from the window index, never from accumulated sums, so a resumed run
// sees exactly the same times as an uninterrupted one.
double Simulation::timeOfWindow(const SimulationConfig& simulation, std::int64_t k) {
  return std::min(static_cast<double>(k) * simulation.chemistry_window, simulation.end_time);
}

bool Simulation::crosses(double interval, std::int64_t k) const {
  if (k == totalWindows()) return true;
  auto slot = [&](std::int64_t j) { return std::floor(timeOfWindow(j) / interval + 1e-9); };
  return slot(k) > slot(k - 1);
}

// Below this angle a triangle has collapsed: its normal, curvature and forces are
// meaningless, and continuing would only write nonsense.
constexpr double kCollapsedAngleDeg = 0.1;
// A relaxation ending with a force above this multiple of the tolerance did not find an
// equilibrium: an error (exit 1). Below it, a warning counted in summary.json.
constexpr double kFarFromTolerance = 100.0;
// A relaxation may thin a coat by stretching its cells at most this much (relative): its
// copies stay on the vertices instead of riding the lipid (docs/proteins.md), so beyond
// this the coat's curvature generation is the mesh's artefact.
constexpr double kLargestCoatThinning = 0.1;

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
          "Drive the shape change more gently (smaller steps in the schedules)",
          m->name(), q.worst_face, q.min_angle_deg, system_.time()));
    // Neighbouring triangles facing apart: the surface folded onto itself, and its
    // curvature and energy mean nothing.
    if (q.min_dihedral_cos < 0.0)
      throw RunError(fmt::format("membrane \"{}\": folded at t = {:.6g} s (neighbouring triangles' normals at "
                                 "cos {:.3f}); the relaxation did not find a smooth shape",
                                 m->name(), system_.time(), q.min_dihedral_cos));
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
  chem->setInterrupt([this] { observer_.duringWindow(); });
  chem->advance(t_end);
  chem->setInterrupt(nullptr);
  system_.collectSurfaceCopies();
  system_.counters.chemistry_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

MinimizerProgressCallback Simulation::progressOf(std::string what) {
  return [this, what = std::move(what)](const MinimizerProgress& p) {
    observer_.onRelaxing(system_, what, p);
    observer_.duringWindow();
  };
}

namespace {
// Membranes and filaments that push on each other relax in turn, each under the other at
// rest, until a membrane relaxation finds nothing left to do; past this many rounds the
// relaxation is reported unconverged. Membranes first: filaments relaxed first against a
// held membrane escape its push by bending sideways, and a bundle below its buckling load
// stops raising the membrane (tried; docs/coupling.md).
constexpr int kMaxCouplingRounds = 50;

}  // namespace

MinimizationResult Simulation::relaxByBody() {
  const bool coupled = !system_.couplingTerms().empty();
  MinimizationResult r{true, 0, 0.0, 0.0, ""};
  for (int round = 0;; ++round) {
    const MinimizationResult membranes = relaxMembranes();
    if (round > 0 && membranes.iterations == 0) break;  // at rest under the filaments' last move
    const MinimizationResult filaments = relaxFilaments();
    r.iterations += membranes.iterations + filaments.iterations;
    r.energy = membranes.energy + filaments.energy;
    r.max_force = std::max(membranes.max_force, filaments.max_force);
    r.converged = membranes.converged && filaments.converged;
    r.stop_reason = !membranes.converged ? membranes.stop_reason : filaments.stop_reason;
    if (!coupled || filaments.iterations == 0) break;
    if (round + 1 == kMaxCouplingRounds) {
      r.converged = false;
      r.stop_reason = fmt::format("membranes and filaments did not come to rest together in {} rounds of "
                                  "relaxing each under the other",
                                  kMaxCouplingRounds);
      break;
    }
  }
  return r;
}

MinimizationResult Simulation::relaxMembranes() {
  MinimizationResult r{true, 0, 0.0, 0.0, ""};
  RunCounters& c = system_.counters;
  ShapeRelaxationSettings settings{mech_.force_tolerance_given ? mech_.force_tolerance : 0.0, mech_.max_iterations, {}};
  bool remeshed = false;
  for (std::size_t i = 0; i < system_.membranes().size(); ++i) {
    Membrane* m = system_.membranes()[i].get();
    settings.progress = progressOf(m->name());
    settings.warm_start = &warm_starts_[i];
    const ShapeRelaxationReport rep = relaxMembraneShape(*m, system_.forceField(), system_.time(), settings);
    c.remesh_seconds += rep.remesh_seconds;
    c.mechanics_seconds -= rep.remesh_seconds;  // counted apart
    c.preconditioner_seconds += rep.factor_seconds + rep.solve_seconds;
    c.preconditioner_factorizations += rep.factorizations;
    remeshed = remeshed || rep.remeshes > 0;
    std::string held;
    if (rep.area_held)
      held += fmt::format("; area held (error {:.2g}), tension {:.6g} pN/nm", rep.area_error, m->equilibrium().tension);
    if (rep.volume_held)
      held += fmt::format("; volume held (error {:.2g}), pressure difference {:.6g} pN/nm^2", rep.volume_error,
                          m->equilibrium().pressure);
    spdlog::debug("t = {:.6g} s: membrane \"{}\" relaxed{} in {} outer steps, {} iterations, {} force evaluations, "
                  "{} constraint evaluations, {} factorizations, {} preconditioner solves, {} remeshes, {} vertices; max "
                  "normal force {:.3g} pN (tolerance {:.3g} pN){}",
                  system_.time(), m->name(), rep.converged ? "" : " (NOT converged: " + rep.stop_reason + ")",
                  rep.outer, rep.iterations, rep.force_evaluations, rep.constraint_evaluations, rep.factorizations,
                  rep.preconditioner_solves, rep.remeshes, rep.vertices,
                  rep.max_normal_force, rep.force_tolerance, held);
    if (rep.held_force > 0 || rep.held_torque > 0)
      spdlog::debug("t = {:.6g} s: membrane \"{}\" held in place by its rigid-body rows against a net force of "
                    "{:.3g} pN and a torque of {:.3g} pN nm",
                    system_.time(), m->name(), rep.held_force, rep.held_torque);
    r.iterations += rep.iterations;
    r.energy += rep.energy;
    if (rep.max_normal_force > r.max_force) r.max_force = rep.max_normal_force;
    if (!rep.converged) {
      r.converged = false;
      r.stop_reason = fmt::format("membrane \"{}\": {} (largest normal force {:.3g} pN, tolerance {:.3g} pN)",
                                  m->name(), rep.stop_reason, rep.max_normal_force, rep.force_tolerance);
    }
    // A result off its targets is not one: the run stops (it went on with warnings, its
    // reduced volume 0.9972 where 0.999 was asked of a 368-vertex sphere).
    if (!rep.converged && rep.targets_unreachable)
      throw RunError(fmt::format("membrane \"{}\": at t = {:.6g} s its area and volume targets cannot be held "
                                 "together (area off by {:.2g}, volume by {:.2g}, relative): a reduced volume "
                                 "above what this mesh encloses at its area? (a finer mesh_size reaches closer to 1)",
                                 m->name(), system_.time(), rep.area_error, rep.volume_error));
    // Converged, yet far: the minimizer's residual (normal displacements, its own
    // multipliers) and the one recomputed at the final positions disagree, which a
    // stiffness near the limit of double precision does (io/resolvable_forces.hpp).
    const std::string why = rep.converged ? "it converged in its own coordinates, but not by the forces recomputed "
                                            "at the final positions (forces too large for double precision to "
                                            "resolve to the tolerance?)"
                                          : rep.stop_reason;
    if (rep.max_normal_force > kFarFromTolerance * rep.force_tolerance)
      throw RunError(fmt::format("membrane \"{}\": the relaxation at t = {:.6g} s ended far from equilibrium "
                                 "(largest normal force {:.3g} pN, over {:g} x its force tolerance {:.3g} pN): {}",
                                 m->name(), system_.time(), rep.max_normal_force, kFarFromTolerance,
                                 rep.force_tolerance, why));
  }
  if (remeshed) system_.layOut();
  return r;
}

MinimizationResult Simulation::relaxFilaments() {
  MinimizationResult r{true, 0, 0.0, 0.0, ""};
  if (FilamentNetwork* net = system_.filaments(); net && net->numPoints() > 0) {
    // On the network's own coordinates: the membranes stay where they are held.
    const Eigen::Index first = 3 * net->offset();
    Eigen::VectorXd x(3 * net->numPoints());
    net->gather(x.data());
    const BodyAtOffsetZero at_zero(*net);
    ForceField::Alone filaments(system_.forceField(), system_.forceField().termsOf(net->name()), *net, first);
    MinimizerSettings filament_settings = mech_;
    // Conjugate gradients, or on request L-BFGS on the network's own Hessian model
    // (filament_preconditioner.hpp): 2.5-9x fewer force evaluations where membranes push,
    // but a bundle pulling a tube then failed to come to rest with its membrane in some
    // windows (docs/filaments.md, Relaxation).
    const bool preconditioned = mech_.precondition_filaments;
    FilamentPreconditioner model;
    filament_settings.kind = preconditioned ? MinimizerKind::kLbfgs : MinimizerKind::kConjugateGradient;
    if (preconditioned) {
      std::vector<char> frozen(static_cast<std::size_t>(net->numPoints()));
      net->frozen(frozen.data());
      if (model.build(net->layout(), net->config().types, x, frozen))
        filament_settings.inverse_hessian = [&model](const Eigen::VectorXd& r, Eigen::VectorXd& z) { model.apply(r, z); };
      else
        spdlog::debug("t = {:.6g} s: the filaments' Hessian model did not factorize; relaxing them unpreconditioned",
                      system_.time());
    }
    filament_settings.progress = progressOf("filaments");
    const long evaluations_before = system_.forceField().forceEvaluations();
    const MinimizationResult f = minimize(filaments, x, filament_settings);
    net->scatter(x.data());
    spdlog::debug("t = {:.6g} s: filaments relaxed{} by {} in {} iterations, {} force evaluations; max force {:.3g} pN "
                  "(tolerance {:.3g} pN)",
                  system_.time(), f.converged ? "" : " (NOT converged: " + f.stop_reason + ")",
                  preconditioned ? "preconditioned L-BFGS" : "CG", f.iterations,
                  system_.forceField().forceEvaluations() - evaluations_before, f.max_force, mech_.force_tolerance);
    r.iterations += f.iterations;
    r.energy += f.energy;
    r.max_force = std::max(r.max_force, f.max_force);
    if (!f.converged) {
      r.converged = false;
      r.stop_reason = fmt::format("filaments: {} (max force {:.3g} pN, tolerance {:.3g} pN)", f.stop_reason,
                                  f.max_force, mech_.force_tolerance);
    }
  }
  return r;
}

MinimizationResult Simulation::relaxAll() {
  Eigen::VectorXd x = system_.coordinates();
  MinimizerSettings settings = mech_;
  settings.progress = progressOf("system");
  const MinimizationResult r = minimize(system_.forceField(), x, settings);
  system_.setCoordinates(x);
  return r;
}

void Simulation::checkRelaxation(const MinimizationResult& r) const {
  if (r.max_force > kFarFromTolerance * mech_.force_tolerance)
    throw RunError(fmt::format("the relaxation at t = {:.6g} s ended far from equilibrium (largest force {:.3g} pN, "
                               "over {:g} x force_tolerance = {:.3g} pN): {}",
                               system_.time(), r.max_force, kFarFromTolerance, kFarFromTolerance * mech_.force_tolerance,
                               r.stop_reason));
}

void Simulation::checkCoats(const std::vector<double>& coverage_before) const {
  for (std::size_t i = 0; i < coverage_before.size(); ++i) {
    const Membrane& m = *system_.membranes()[i];
    const double after = m.coatCoverage();
    spdlog::debug("t = {:.6g} s: membrane \"{}\": coat coverage {:.4g} -> {:.4g} through the relaxation", system_.time(),
                  m.name(), coverage_before[i], after);
    if (after < (1.0 - kLargestCoatThinning) * coverage_before[i])
      throw RunError(fmt::format(
          "membrane \"{}\": the relaxation at t = {:.6g} s thinned the coat from a mean coverage of {:.3g} to {:.3g} by "
          "stretching its cells (more than {:g}%): the copies follow the lipid's flow, but the mesh smears the coat's "
          "edge over about a cell's width: a smaller mesh_size keeps it sharper (docs/proteins.md, curvature "
          "generation, gives the thinning against mesh_size)",
          m.name(), system_.time(), coverage_before[i], after, 100.0 * kLargestCoatThinning));
  }
}

void Simulation::checkCrossings(const char* when) const {
  for (const MembraneBeadExclusion* term : system_.couplingTerms())
    if (const auto crossing = findMembraneCrossing(term->membrane(), term->network()))
      throw RunError(fmt::format("t = {:.6g} s, {}: {}; the excluded volume did not keep it out (a smaller "
                                 "chemistry_window or a larger [membrane_filament] stiffness may)",
                                 system_.time(), when, crossing->describe(term->membrane())));
}

void Simulation::checkMembranesApart() const {
  // Membranes do not push on each other: one moved through another (a vesicle swelling
  // into its neighbour) is no state the model describes, and stops the run.
  if (const auto c = findCrossingMembranes(system_.membranes()))
    throw RunError(fmt::format("t = {:.6g} s, after the relaxation: membranes \"{}\" and \"{}\" pass through each "
                               "other ({}); membranes do not push on each other in cortex, so nothing keeps them "
                               "apart: start them farther apart or change what drives them together",
                               system_.time(), c->a->name(), c->b->name(), c->where));
}

// A minimizer that met a non-finite energy knows only the total: name the terms that are
// not finite where the bodies stand (a bending stiffness of 1e300 said only "energy is
// inf ... check parameters for impossible values").
std::string Simulation::nonFiniteTerms() {
  std::string terms;
  for (const TermEnergy& t : system_.forceField().breakdown(system_.coordinates()))
    if (!std::isfinite(t.energy))
      terms += fmt::format("{}\"{}\" of \"{}\" ({:g} pN·nm)", terms.empty() ? "" : ", ", t.name, t.owner, t.energy);
  return terms.empty() ? "" : "; not finite where the bodies are: the energy term " + terms + ": check its parameters";
}

MinimizationResult Simulation::relax() {
  // Chemistry may have grown, bound or branched filaments since the last relaxation.
  if (system_.filaments()) system_.layOut();
  checkCrossings("after the chemistry window");
  MinimizationResult r{true, 0, 0.0, 0.0, "nothing to relax"};
  RunCounters& c = system_.counters;
  const bool by_body = mech_.kind == MinimizerKind::kAuto;
  for (ShapeRelaxationWarmStart& w : warm_starts_) w.newWindow();
  std::vector<double> coverage;
  if (system_.hasMechanics()) {
    const auto start = std::chrono::steady_clock::now();
    const double force_seconds = system_.forceField().forceSeconds();
    for (const auto& m : system_.membranes()) coverage.push_back(m->coatCoverage()), m->beginLipidFlow();
    try {
      r = by_body ? relaxByBody() : relaxAll();
    } catch (const RunError& e) {
      throw RunError(e.what() + nonFiniteTerms());
    }
    c.force_seconds += system_.forceField().forceSeconds() - force_seconds;
    ++c.minimizations;
    c.minimizer_iterations += r.iterations;
    c.last_max_force = r.max_force;
    c.mechanics_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  if (!by_body) remeshMembranes();  // the shape relaxation remeshes within
  // The proteins ride the lipid through the relaxation's deformation (Membrane::beginLipidFlow).
  for (const auto& m : system_.membranes()) m->endLipidFlow();
  checkCoats(coverage);  // empty without mechanics: nothing relaxed
  checkMeshes();
  checkCrossings("after the relaxation");
  checkMembranesApart();
  checkRelaxation(r);
  // Membranes and filaments moved: confinement, loads, tensions and binding partners
  // change the rates.
  const auto feedback_start = std::chrono::steady_clock::now();
  system_.updateFeedback();
  c.feedback_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - feedback_start).count();
  if (!r.converged) {
    ++c.unconverged_minimizations;
    // Under "auto" each body's reason carries its own force and tolerance.
    spdlog::warn("t = {:.6g} s: relaxation stopped before convergence after {} iterations: {}{}", system_.time(),
                 r.iterations, r.stop_reason,
                 by_body ? "" : fmt::format(" (max force {:.3g} pN > tolerance {:.3g} pN)", r.max_force,
                                            mech_.force_tolerance));
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
