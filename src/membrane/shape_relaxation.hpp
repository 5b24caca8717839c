// Relaxing a membrane to its minimum-energy shape: what every window does to every
// membrane (thesis 2.2.2 energies; method after Surface Evolver and Mem3DG).
//
// Outer loop:
//   1. vertex normals n_v (area-weighted) at the current positions x0;
//   2. variables u_v, x_v = x0_v + u_v n_v: normal displacements only. A fluid membrane's
//      energy does not change when vertices slide within the surface, so over all 3N
//      coordinates a minimizer drifts along that null space until triangles collapse or
//      fold; over normal displacements that space is gone;
//   3. constrained, preconditioned L-BFGS over u (mech/constrained_lbfgs.hpp): exact total
//      area and enclosed volume where the membrane asks for them (their Lagrange
//      multipliers are the tension and the pressure difference), the six rigid-body modes
//      fixed (exact null modes the discretization breaks at round-off level), and the
//      Sobolev metric P = κ (L + εM) M⁻¹ (L + εM) (sobolev_preconditioner.hpp), in which
//      the number of iterations does not grow with the mesh size;
//   4. once some vertex has moved a strain |u_v| (2|H_v| + 1/R) of 0.5: tangential
//      relocation, or the adaptive remesher when the shape changed a lot or an angle fell
//      below 20°; back to 1.
// Converged when the largest normal residual force |n_v · (∇E − λ_A ∇A − λ_V ∇V)| is below
// the tolerance right after an outer step that moved no vertex by more than a strain of
// 0.005. If the shape changed since the last remeshing (summed strain > 0.3, or an angle
// below 25°), it is remeshed once more and relaxed again: the result is always relaxed on
// its final mesh (a mesh left as the remesher made it carries curvature hot spots).
// Targets the constraints cannot reach at once (a sphere asked for v < 1) are approached
// in steps (continuation).
#pragma once

#include <cstdint>
#include <string>

#include "mech/constrained_lbfgs.hpp"
#include "mech/force_field.hpp"
#include "mech/minimizer.hpp"
#include "membrane/membrane.hpp"
#include "membrane/sobolev_preconditioner.hpp"

namespace cortex {

// What a relaxation of a membrane leaves to the next one of the same membrane: the
// factorization of the membrane's RelaxationMetric (with its fill-reducing ordering while
// the mesh keeps its connectivity), and, within a window, derived columns and the L-BFGS
// pairs. Membranes pushed by filaments are relaxed several times per window
// (Simulation::relaxByBody), each time a little away from the last: the pairs cut their
// force evaluations by 16-24% on three coupled examples (docs/coupling.md; an earlier
// build had measured no gain). Everything here is a cache of
// state a checkpoint holds or of the window so far: newWindow() drops what a resumed run
// could not rebuild, and a missing factorization is rebuilt from the metric's positions.
struct ShapeRelaxationWarmStart {
  SobolevPreconditioner preconditioner;
  bool factored = false;
  std::uint64_t connectivity = 0;  // Membrane::connectivityVersion() it was factored for
  // P^-1 of the rigid-mode rows under this factorization (ConstrainedProblem::keptLinearW),
  // and the rows they were computed for: six solves per outer step saved while the rows
  // only turn a little with the normals.
  Eigen::MatrixXd rigid_w, rigid_rows;
  // The L-BFGS pairs of the last relaxation: a membrane relaxed again in the same window
  // (in turn with filaments, docs/coupling.md) starts with the curvature it learnt.
  LbfgsMemory memory;

  void forgetRigidColumns() {
    rigid_w.resize(0, 0);
    rigid_rows.resize(0, 0);
  }
  // The rigid columns and the L-BFGS pairs start afresh with every window, where a
  // resumed run starts; the factorization stays (a resumed run rebuilds the same one from
  // the RelaxationMetric).
  void newWindow() {
    forgetRigidColumns();
    memory.clear();
  }
};

struct ShapeRelaxationSettings {
  double force_tolerance = 0.0;  // pN, largest normal residual force on a vertex; 0: naturalForceTolerance
  long max_iterations = 20000;   // L-BFGS iterations over all outer steps
  MinimizerProgressCallback progress;  // optional, after every outer step
  ShapeRelaxationWarmStart* warm_start = nullptr;  // optional: kept by the caller between relaxations
};

// The membrane's own force scale at time t, the tolerance when none is given: the force
// its bending (and tension) puts on a vertex of mean area Ā when the shape is off by its
// own size R = sqrt(A/4π), p* Ā with p* = κ/R³ + |γ|/R, at most 0.1 pN. A fixed
// tolerance in pN is loose for large, soft vesicles (a 1 µm vesicle at 14k vertices has
// p* Ā ≈ 1e-4 pN; at 0.1 pN its relaxation toward v = 0.9 stopped 12% above the minimum
// energy) and needlessly strict for small, stiff ones.
double naturalForceTolerance(const Membrane& m, double t);

struct ShapeRelaxationReport {
  bool converged = false;
  std::string stop_reason;
  int outer = 0;  // outer steps
  long iterations = 0;
  long force_evaluations = 0;
  long constraint_evaluations = 0;
  long preconditioner_solves = 0;
  int factorizations = 0;
  int remeshes = 0;
  int continuation_steps = 0;  // times the targets had to be approached in steps
  double seconds = 0.0, factor_seconds = 0.0, solve_seconds = 0.0, force_seconds = 0.0, remesh_seconds = 0.0;
  double force_tolerance = 0.0;   // pN, the one used
  double energy = 0.0;            // pN·nm, the membrane's terms
  double max_normal_force = 0.0;  // pN, the converged quantity (the rigid rows' reactions taken out)
  double max_force = 0.0;         // pN, largest |∇E − λ·∇c| on one vertex, tangential included
  // What the rigid-body rows hold the membrane against (docs/membrane.md): the net force
  // (pN) and torque about the area centroid (pN·nm) of their reactions. Zero for a free
  // membrane whose tangential forces vanish; a coat on the vertices makes them finite.
  double held_force = 0.0, held_torque = 0.0;
  bool area_held = false, volume_held = false;   // which constraints were exact
  // The held area and volume could not be reached together, even approached in steps
  // (a reduced volume above what the mesh can enclose at its area).
  bool targets_unreachable = false;
  double area_error = 0.0, volume_error = 0.0;  // relative to the targets (held ones only)
  Index vertices = 0;
};

// Relaxes membrane m under its terms in `field` (EnergyTerm::owner == m.name()) with the
// parameters and targets of time t. Positions change in place and the mesh may be
// remeshed (its vertex count changes: lay the System out again). Writes the multipliers
// and the strain since the last remeshing into m.equilibrium().
ShapeRelaxationReport relaxMembraneShape(Membrane& m, ForceField& field, double t, const ShapeRelaxationSettings& s);

}  // namespace cortex
