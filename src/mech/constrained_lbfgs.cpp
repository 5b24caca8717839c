#include "mech/constrained_lbfgs.hpp"

#include "mech/minimizer.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace cortex {
namespace {

using detail::maxAbs;

// Linearization of the constraints at an iterate: Jacobian J, W = P^-1 J^T, S^-1.
struct ConstraintFrame {
  Eigen::MatrixXd jac, w, s_inv;
  bool empty() const { return jac.rows() == 0; }
  // P-orthogonal projection onto ker J of a vector z.
  Eigen::VectorXd project(const Eigen::VectorXd& z) const {
    if (empty()) return z;
    return z - w * (s_inv * (jac * z));
  }
  Eigen::VectorXd multipliers(const Eigen::VectorXd& g) const {
    if (empty()) return Eigen::VectorXd();
    // (W^T J^T)^-1 W^T g, so that W^T r = 0 (J W is symmetric only when W is fresh).
    return s_inv.transpose() * (w.transpose() * g);
  }
};

}  // namespace

ConstrainedLbfgsResult minimizeConstrained(ConstrainedProblem& p, Eigen::VectorXd& u,
                                           const ConstrainedLbfgsSettings& s, LbfgsMemory& memory) {
  ConstrainedLbfgsResult r;
  const int m = p.numConstraints();
  const Eigen::VectorXd scale = p.constraintScale();
  const Eigen::VectorXd u_start = u;
  auto moveOf = [&](const Eigen::VectorXd& du) {
    return s.move_scale.size() ? du.cwiseProduct(s.move_scale).cwiseAbs().maxCoeff() : maxAbs(du);
  };
  Eigen::VectorXd c;
  Eigen::MatrixXd jac;

  Eigen::MatrixXd linear_w;  // W columns of the linear constraints
  auto frameAt = [&](const Eigen::VectorXd& at) {
    ConstraintFrame f;
    if (m == 0) return f;
    p.constraints(at, c, jac);
    ++r.constraint_evaluations;
    f.jac = jac;
    const int linear = p.numLinearConstraints();
    if (const Eigen::MatrixXd* kept = p.keptLinearW();
        linear > 0 && linear_w.cols() != linear && kept && kept->cols() == linear && kept->rows() == jac.cols())
      linear_w = *kept;
    if (linear > 0 && linear_w.cols() == linear) {
      // The linear rows' Jacobian never changes: their columns of W are computed once.
      f.w.resize(jac.cols(), m);
      if (m > linear) f.w.leftCols(m - linear) = p.precondition(jac.topRows(m - linear).transpose());
      f.w.rightCols(linear) = linear_w;
    } else {
      f.w = p.precondition(jac.transpose());
      if (linear > 0) {
        linear_w = f.w.rightCols(linear);
        p.keepLinearW(linear_w);
      }
    }
    f.s_inv = (jac * f.w).inverse();
    return f;
  };
  // The frame at a restored point: its Jacobian with W kept from an earlier frame. The
  // projector stays exact (J Pi = 0) and r stays W-orthogonal, so directions still
  // descend; W is refreshed every few iterations.
  auto frameWith = [&](const Eigen::VectorXd& at, const ConstraintFrame& old) {
    ConstraintFrame f;
    if (m == 0) return f;
    p.constraints(at, c, jac);
    ++r.constraint_evaluations;
    f.jac = jac;
    f.w = old.w;
    f.s_inv = (jac * f.w).inverse();
    return f;
  };
  int frame_age = 0;
  auto satisfied = [&](const Eigen::VectorXd& cv) {
    for (int i = 0; i < m; ++i)
      if (std::abs(cv[i]) > s.constraint_tolerance * scale[i]) return false;
    return true;
  };
  auto violation = [&](const Eigen::VectorXd& cv) { return cv.cwiseQuotient(scale).cwiseAbs().maxCoeff(); };
  // Restoration along the frame's W, v -= W (J W)^-1 c. The values of c are cheap, its
  // Jacobian is not (a pass over the mesh), so J W is the frame's (chord steps) until a
  // step reduces the violation less than 4-fold; then J is evaluated at v (a Newton step)
  // and its J W used from there on. Both converge to the same point of the manifold
  // along W. The Jacobian at the restored point, which the next frame needs, is left to
  // frameWith (after the line search accepted the point).
  auto restore = [&](Eigen::VectorXd& v, const ConstraintFrame& f) {
    if (m == 0) return true;
    Eigen::MatrixXd s_inv = f.s_inv;
    double previous = std::numeric_limits<double>::infinity();
    for (int it = 0; it < 30; ++it) {
      p.constraintValues(v, c);
      ++r.constraint_evaluations;
      if (satisfied(c)) return true;
      const double now = violation(c);
      if (!(now <= 0.25 * previous)) {
        p.constraints(v, c, jac);
        ++r.constraint_evaluations;
        s_inv = (jac * f.w).inverse();
      }
      previous = now;
      v -= f.w * (s_inv * c);
    }
    return false;
  };

  // No start from here: u back where it was, the caller approaches the targets in steps.
  auto infeasibleStart = [&] {
    u = u_start;
    r.stop_reason = kInfeasibleStart;
    return r;
  };
  Eigen::VectorXd g(u.size()), g_new(u.size()), u_new(u.size());
  double value = 0.0;
  bool evaluated = false;
  bool on_manifold = true;
  if (m > 0) {
    p.constraintValues(u, c);
    ++r.constraint_evaluations;
    on_manifold = satisfied(c);
  }
  if (on_manifold) {
    // A start already at rest (the step confirming a converged shape on fresh normals, a
    // membrane nothing moved) is recognized with least-squares multipliers, which need no
    // preconditioner solve; the frame below costs one per constraint.
    value = p.valueAndGradient(u, g);
    ++r.evaluations;
    evaluated = true;
    if (std::isfinite(value)) {
      Eigen::VectorXd lambda_ls;
      if (m > 0) {
        p.constraints(u, c, jac);
        ++r.constraint_evaluations;
        lambda_ls = jac.transpose().colPivHouseholderQr().solve(g);
      }
      const Eigen::VectorXd rest = m > 0 ? Eigen::VectorXd(g - jac.transpose() * lambda_ls) : g;
      const double residual = maxAbs(rest);
      if (residual <= s.tolerance &&
          (s.step_tolerance <= 0 || maxAbs(p.precondition(rest).col(0)) <= s.step_tolerance)) {
        r.converged = true;
        r.value = value;
        r.max_residual = residual;
        r.multipliers = lambda_ls;
        if (m > 0) r.constraint_values = c;
        return r;
      }
    }
  }
  ConstraintFrame frame = frameAt(u);
  if (!on_manifold) {
    // A restoration that has to deform the shape more than a refresh allows (e.g. a large
    // jump of the reduced volume) counts as infeasible: the caller approaches the targets
    // in steps instead of crumpling the shape in one projection.
    if (!restore(u, frame) || moveOf(u - u_start) > s.max_total_move) return infeasibleStart();
    frame = frameAt(u);
  }
  if (!evaluated) {
    value = p.valueAndGradient(u, g);
    ++r.evaluations;
  }
  // A restoration that carried the shape into a forbidden state (infinite energy: e.g. a
  // membrane onto a filament bead) counts as infeasible too: no line search can start
  // from there, but the caller's smaller steps towards the targets may not go there.
  if (!std::isfinite(value) && u != u_start) return infeasibleStart();
  Eigen::VectorXd lambda = frame.multipliers(g);
  Eigen::VectorXd res = m ? Eigen::VectorXd(g - frame.jac.transpose() * lambda) : g;

  for (r.iterations = 0; r.iterations < s.max_iterations; ++r.iterations) {
    r.max_residual = maxAbs(res);
    const bool small_residual = r.max_residual <= s.tolerance;
    if (small_residual && s.step_tolerance <= 0) {
      r.converged = true;
      break;
    }
    if (moveOf(u - u_start) > s.max_total_move) {
      r.refresh = true;
      r.stop_reason = "parametrization needs refreshing";
      break;
    }
    // Two-loop recursion with H0 = gamma * Pi P^-1.
    Eigen::VectorXd q = res;
    std::vector<double> alpha(memory.pairs.size());
    for (std::size_t i = memory.pairs.size(); i-- > 0;) {
      alpha[i] = memory.pairs[i].rho * memory.pairs[i].s.dot(q);
      q -= alpha[i] * memory.pairs[i].y;
    }
    Eigen::VectorXd z = frame.project(p.precondition(q).col(0));
    if (s.scale_initial_hessian && !memory.pairs.empty()) {
      // Scale H0 so that it matches the latest pair in the P metric.
      const auto& last = memory.pairs.back();
      const Eigen::VectorXd py = frame.project(p.precondition(last.y).col(0));
      const double yhy = last.y.dot(py);
      if (yhy > 0) z *= last.s.dot(last.y) / yhy;
    }
    for (std::size_t i = 0; i < memory.pairs.size(); ++i) {
      const double beta = memory.pairs[i].rho * memory.pairs[i].y.dot(z);
      z += (alpha[i] - beta) * memory.pairs[i].s;
    }
    Eigen::VectorXd d = -frame.project(z);
    double slope = res.dot(d);
    if (!(slope < 0.0)) {
      memory.clear();
      d = -frame.project(p.precondition(res).col(0));
      slope = res.dot(d);
      if (!(slope < 0.0)) {
        r.converged = small_residual;
        if (!small_residual) r.stop_reason = "no descent direction";
        break;
      }
    }
    if (small_residual && maxAbs(d) <= s.step_tolerance) {
      r.converged = true;
      break;
    }
    double step = std::min(1.0, s.max_move / moveOf(d));
    bool accepted = false;
    double value_new = value;
    const double roundoff = 1e-13 * std::abs(value) + 1e-300;
    for (int trial = 0; trial < 30; ++trial) {
      u_new = u + step * d;
      if (!restore(u_new, frame) || !p.admissible(u_new)) {
        step *= 0.3;
        continue;
      }
      value_new = p.valueAndGradient(u_new, g_new);
      ++r.evaluations;
      const double expected = step * slope;
      if (std::isfinite(value_new) && value_new <= value + 1e-4 * expected + roundoff) {
        accepted = true;
        break;
      }
      // Quadratic interpolation of the decrease, kept within [0.1, 0.5] of the step.
      double next = std::isfinite(value_new) ? -0.5 * slope * step * step / (value_new - value - slope * step)
                                             : 0.1 * step;
      step = std::clamp(next, 0.1 * step, 0.5 * step);
    }
    if (!accepted) {
      if (memory.pairs.empty()) {
        r.stop_reason = "line search found no lower energy along the preconditioned gradient";
        break;
      }
      memory.clear();
      continue;
    }
    ++frame_age;
    const bool refresh_w = frame_age >= s.frame_refresh;
    if (refresh_w) frame_age = 0;
    const ConstraintFrame frame_new = refresh_w ? frameAt(u_new) : frameWith(u_new, frame);
    const Eigen::VectorXd lambda_new = frame_new.multipliers(g_new);
    Eigen::VectorXd res_new = m ? Eigen::VectorXd(g_new - frame_new.jac.transpose() * lambda_new) : g_new;
    LbfgsMemory::Pair pair{u_new - u, res_new - res, 0.0};
    const double sy = pair.s.dot(pair.y);
    if (sy > 1e-12 * pair.s.norm() * pair.y.norm()) {
      pair.rho = 1.0 / sy;
      memory.pairs.push_back(std::move(pair));
      if (static_cast<int>(memory.pairs.size()) > s.memory) memory.pairs.pop_front();
    }
    u.swap(u_new);
    g.swap(g_new);
    value = value_new;
    frame = frame_new;
    lambda = lambda_new;
    res.swap(res_new);
  }
  if (!r.converged && r.stop_reason.empty()) r.stop_reason = "maximum iterations reached";
  r.value = value;
  r.max_residual = maxAbs(res);
  r.multipliers = lambda;
  if (m) {
    p.constraints(u, c, jac);
    r.constraint_values = c;
  }
  return r;
}

}  // namespace cortex
