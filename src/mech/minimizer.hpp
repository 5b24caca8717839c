// Energy minimization to a force tolerance: nonlinear conjugate gradients or L-BFGS.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

#include "mech/objective.hpp"

namespace cortex {

// kAuto: each membrane by its shape relaxation (membrane/shape_relaxation.hpp), then the
// filaments by conjugate gradients (or, with precondition_filaments, by L-BFGS on their
// Hessian model); kConjugateGradient, kLbfgs: everything at once over all coordinates
// (membranes need penalty area and volume terms then).
enum class MinimizerKind { kAuto, kConjugateGradient, kLbfgs };

// Where a minimization stands, for progress reports during long relaxations.
struct MinimizerProgress {
  long iterations = 0;
  double max_force = 0.0;  // pN, the converged quantity
  double tolerance = 0.0;  // pN
};
// Called once per iteration (or outer step); must be cheap: the caller throttles output.
using MinimizerProgressCallback = std::function<void(const MinimizerProgress&)>;

struct MinimizerSettings {
  MinimizerKind kind = MinimizerKind::kAuto;
  double force_tolerance = 0.1;  // pN: converged when the force on every point is below it
  // Whether the config gave force_tolerance: if not, membranes under kAuto converge on
  // their own force scale instead (membrane/shape_relaxation.hpp).
  bool force_tolerance_given = false;
  long max_iterations = 100000;
  double max_step = 20.0;        // nm: largest move of any coordinate in one line search
  int lbfgs_memory = 10;
  // kAuto only: the filaments by L-BFGS on their Hessian model
  // (filament/filament_preconditioner.hpp) instead of conjugate gradients.
  bool precondition_filaments = false;
  // L-BFGS only, optional: z = H0 r, its initial inverse Hessian (a preconditioner). Without
  // it, the identity scaled by the latest curvature pair.
  std::function<void(const Eigen::VectorXd& r, Eigen::VectorXd& z)> inverse_hessian;
  MinimizerProgressCallback progress;  // optional
};

struct MinimizationResult {
  bool converged = false;
  long iterations = 0;
  double energy = 0.0;
  double max_force = 0.0;  // pN, largest force on one point (maxPointForce)
  std::string stop_reason;
};

// Minimizes f starting from x (overwritten with the result). Throws RunError when the
// energy or forces become NaN/inf or the energy runs away to -infinity.
MinimizationResult minimize(Objective& f, Eigen::VectorXd& x, const MinimizerSettings& settings);

namespace detail {
MinimizationResult conjugateGradient(Objective& f, Eigen::VectorXd& x, const MinimizerSettings& s);
MinimizationResult lbfgs(Objective& f, Eigen::VectorXd& x, const MinimizerSettings& s);
// Shared guards of both methods.
void checkFinite(double energy, const Eigen::VectorXd& gradient, const char* where);
// Runaway guard: the energy is unbounded below if it reaches -1e30 or the coordinates
// travel from `start` more than 100 times the extent of `start` (plus 1e4 nm).
void checkBounded(double energy, const Eigen::VectorXd& x, const Eigen::VectorXd& start);
// Largest magnitude (0 for an empty vector); infinity when any entry is not finite:
// Eigen's maxCoeff may skip a NaN, and a residual of NaN must not pass for converged.
double maxAbs(const Eigen::VectorXd& v);
// Largest force on one point, |(g_3i, g_3i+1, g_3i+2)| over the points i of a gradient
// laid out x y z per point (every Objective here is): unlike the largest component it does
// not depend on how the axes are oriented, so a rotated system converges alike. Infinity
// when any entry is not finite.
double maxPointForce(const Eigen::VectorXd& g);
}  // namespace detail

}  // namespace cortex
