// Limited-memory BFGS with the two-loop recursion (Nocedal & Wright 2006, alg. 7.4). The
// initial inverse Hessian is the settings' preconditioner when given, else the identity
// scaled by s.y / y.y of the latest pair.
#include <deque>
#include <vector>

#include "mech/line_search.hpp"
#include "mech/minimizer.hpp"

namespace cortex::detail {
namespace {

struct CurvaturePair {
  Eigen::VectorXd s, y;
  double rho;
};

Eigen::VectorXd twoLoopDirection(const Eigen::VectorXd& g, const std::deque<CurvaturePair>& pairs,
                                 const MinimizerSettings& settings) {
  Eigen::VectorXd q = -g;
  std::vector<double> alpha(pairs.size());
  for (std::size_t i = pairs.size(); i-- > 0;) {
    alpha[i] = pairs[i].rho * pairs[i].s.dot(q);
    q -= alpha[i] * pairs[i].y;
  }
  if (settings.inverse_hessian) {
    Eigen::VectorXd z;
    settings.inverse_hessian(q, z);
    q.swap(z);
  } else if (!pairs.empty()) {
    q *= pairs.back().s.dot(pairs.back().y) / pairs.back().y.squaredNorm();
  }
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const double beta = pairs[i].rho * pairs[i].y.dot(q);
    q += (alpha[i] - beta) * pairs[i].s;
  }
  return q;
}

}  // namespace

MinimizationResult lbfgs(Objective& f, Eigen::VectorXd& x, const MinimizerSettings& s) {
  Eigen::VectorXd g(x.size()), x_new(x.size()), g_new(x.size());
  double energy = f.valueAndGradient(x, g);
  checkFinite(energy, g, "at the start of minimization");
  const Eigen::VectorXd start = x;
  std::deque<CurvaturePair> pairs;
  const LineSearchParams params{1e-4, 0.9, 40};
  MinimizationResult r;
  for (r.iterations = 0; r.iterations < s.max_iterations; ++r.iterations) {
    r.max_force = maxPointForce(g);
    if (r.max_force <= s.force_tolerance) {
      r.converged = true;
      break;
    }
    if (s.progress) s.progress({r.iterations, r.max_force, s.force_tolerance});
    Eigen::VectorXd d = twoLoopDirection(g, pairs, s);
    double slope = g.dot(d);
    if (slope >= 0.0) {  // memory lost positive definiteness: start over
      pairs.clear();
      d = twoLoopDirection(g, pairs, s);
      slope = g.dot(d);
    }
    const double cap = s.max_step / maxAbs(d);
    // A preconditioned direction has a length: its unit step is the model's minimum.
    const double initial = pairs.empty() && !s.inverse_hessian ? cap : std::min(1.0, cap);
    const LineSearchResult ls = wolfeLineSearch(f, x, energy, slope, d, initial, cap, params, x_new, g_new);
    if (!ls.ok) {
      if (pairs.empty()) {
        r.stop_reason = "line search found no lower energy along the steepest descent";
        break;
      }
      pairs.clear();
      continue;
    }
    checkFinite(ls.value, g_new, "during minimization");
    checkBounded(ls.value, x_new, start);
    CurvaturePair p{x_new - x, g_new - g, 0.0};
    const double sy = p.s.dot(p.y);
    if (sy > 1e-12 * p.s.norm() * p.y.norm()) {
      p.rho = 1.0 / sy;
      pairs.push_back(std::move(p));
      if (static_cast<int>(pairs.size()) > s.lbfgs_memory) pairs.pop_front();
    }
    x.swap(x_new);
    g.swap(g_new);
    energy = ls.value;
  }
  if (!r.converged && r.stop_reason.empty()) r.stop_reason = "maximum iterations reached";
  r.energy = energy;
  r.max_force = maxPointForce(g);
  return r;
}

}  // namespace cortex::detail
