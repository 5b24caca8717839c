// Preconditioned L-BFGS on a manifold of equality constraints: how membranes are relaxed
// (membrane/shape_relaxation.hpp), generic over the problem.
//
// Minimizes f(u) subject to c(u) = 0 (a few global constraints, e.g. total area and
// enclosed volume) with
//  - the preconditioner P (an SPD approximation of the Hessian) as the initial inverse
//    Hessian of L-BFGS, restricted to the constraints' tangent space by the
//    P-orthogonal projector  Pi z = z - W S^-1 J z,  W = P^-1 J^T, S = J W;
//  - Lagrange multipliers lambda = S^-1 W^T g at every iterate; r = g - J^T lambda is
//    the residual (force) that must fall below the tolerance;
//  - after every trial step a restoration back onto c = 0 along W: chord steps with the
//    frame's J W (constraint values only), a Newton step with the Jacobian at the point
//    whenever a chord step reduces the violation less than 4-fold. No energy evaluation;
//    it converges to round-off in 2-4 cheap steps;
//  - a backtracking (Armijo) line search on the restored points that also refuses
//    geometrically inadmissible trial points (folded triangles).
// With no constraints it is plain preconditioned L-BFGS.
#pragma once

#include <Eigen/Core>
#include <deque>
#include <string>

#include "core/types.hpp"

namespace cortex {

class ConstrainedProblem {
 public:
  virtual ~ConstrainedProblem() = default;
  virtual Index size() const = 0;
  virtual int numConstraints() const = 0;
  // Objective and its gradient: one "force evaluation".
  virtual double valueAndGradient(const Eigen::VectorXd& u, Eigen::VectorXd& g) = 0;
  // Constraint values (zero when satisfied) and Jacobian (rows = constraints); cheap.
  virtual void constraints(const Eigen::VectorXd& u, Eigen::VectorXd& c, Eigen::MatrixXd& jacobian) = 0;
  // The values alone: most restoration steps need no Jacobian. Override when cheaper.
  virtual void constraintValues(const Eigen::VectorXd& u, Eigen::VectorXd& c) {
    Eigen::MatrixXd unused;
    constraints(u, c, unused);
  }
  // |c_i| <= constraint_tolerance * scale_i counts as satisfied.
  virtual Eigen::VectorXd constraintScale() const = 0;
  // The last numLinearConstraints() rows are linear with a constant Jacobian (e.g. rigid
  // modes): their columns of W = P^-1 J^T are computed once per call.
  virtual int numLinearConstraints() const { return 0; }
  // Those columns kept by the problem from an earlier call with the same P, if any (null:
  // computed, then offered to keepLinearW). The rows may have changed a little since: any
  // W with J W invertible keeps the projection exact (J Pi = 0), and directions descend
  // because the residual stays W-orthogonal.
  virtual const Eigen::MatrixXd* keptLinearW() const { return nullptr; }
  virtual void keepLinearW(const Eigen::MatrixXd& /*w*/) {}
  // z = P^-1 r for each column.
  virtual Eigen::MatrixXd precondition(const Eigen::MatrixXd& r) = 0;
  // False if u is geometrically unacceptable (e.g. a folded triangle).
  virtual bool admissible(const Eigen::VectorXd& u) = 0;
};

inline constexpr const char* kInfeasibleStart = "could not satisfy the constraints at the start";

struct ConstrainedLbfgsSettings {
  double tolerance = 1e-3;        // on max_i |r_i|
  // With step_tolerance > 0, converged also needs the quasi-Newton step from the point
  // (the move the next iteration would make at full length) within it, max_i |du_i| in
  // the variables' own units: a small residual can still hide a long, soft mode far from
  // its minimum.
  double step_tolerance = 0.0;
  long max_iterations = 1000;
  int memory = 10;
  // Moves are measured as max_i |du_i| * move_scale_i (move_scale empty: all ones).
  Eigen::VectorXd move_scale;
  double max_move = 10.0;         // largest move in one step
  double max_total_move = 1e300;  // stop (not converged) once the move from the start exceeds it
  bool scale_initial_hessian = false;  // gamma = s.y / y.P^-1 y (false: P is trusted as is)
  double constraint_tolerance = 1e-10;
  int frame_refresh = 10;  // iterations between recomputations of W = P^-1 J^T
};

struct ConstrainedLbfgsResult {
  bool converged = false;
  bool refresh = false;  // stopped because max_total_move was reached
  long iterations = 0;
  long evaluations = 0;        // objective+gradient evaluations
  long constraint_evaluations = 0;
  double value = 0.0;
  double max_residual = 0.0;
  Eigen::VectorXd multipliers;
  Eigen::VectorXd constraint_values;
  std::string stop_reason;
};

// The curvature pairs, kept by the caller across calls when the variables keep their
// meaning (same mesh, slightly rotated normals).
struct LbfgsMemory {
  struct Pair {
    Eigen::VectorXd s, y;
    double rho;
  };
  std::deque<Pair> pairs;
  void clear() { pairs.clear(); }
};

ConstrainedLbfgsResult minimizeConstrained(ConstrainedProblem& p, Eigen::VectorXd& u,
                                           const ConstrainedLbfgsSettings& s, LbfgsMemory& memory);

}  // namespace cortex
