// Nonlinear conjugate gradients, Polak-Ribiere+ (Nocedal & Wright 2006, sec. 5.2),
// restarted along the steepest descent whenever the direction stops descending or a line
// search fails.
#include "mech/line_search.hpp"
#include "mech/minimizer.hpp"

namespace cortex::detail {

MinimizationResult conjugateGradient(Objective& f, Eigen::VectorXd& x, const MinimizerSettings& s) {
  Eigen::VectorXd g(x.size()), x_new(x.size()), g_new(x.size());
  double energy = f.valueAndGradient(x, g);
  checkFinite(energy, g, "at the start of minimization");
  const Eigen::VectorXd start = x;
  Eigen::VectorXd d = -g;
  double previous_step = 0.0, previous_slope = 0.0;
  const LineSearchParams params{1e-4, 0.1, 40};
  MinimizationResult r;
  bool restarted = true;
  for (r.iterations = 0; r.iterations < s.max_iterations; ++r.iterations) {
    r.max_force = maxPointForce(g);
    if (r.max_force <= s.force_tolerance) {
      r.converged = true;
      break;
    }
    if (s.progress) s.progress({r.iterations, r.max_force, s.force_tolerance});
    double slope = g.dot(d);
    if (slope >= 0.0) {
      d = -g;
      slope = -g.squaredNorm();
      restarted = true;
    }
    const double cap = s.max_step / maxAbs(d);
    const double initial = restarted ? cap : std::min(cap, previous_step * previous_slope / slope);
    const LineSearchResult ls = wolfeLineSearch(f, x, energy, slope, d, initial, cap, params, x_new, g_new);
    if (!ls.ok) {
      if (restarted) {
        r.stop_reason = "line search found no lower energy along the steepest descent";
        break;
      }
      d = -g;
      restarted = true;
      continue;
    }
    checkFinite(ls.value, g_new, "during minimization");
    checkBounded(ls.value, x_new, start);
    const double beta = std::max(0.0, g_new.dot(g_new - g) / g.squaredNorm());
    previous_step = ls.step;
    previous_slope = slope;
    x.swap(x_new);
    g.swap(g_new);
    energy = ls.value;
    d = -g + beta * d;
    restarted = beta == 0.0;
  }
  if (!r.converged && r.stop_reason.empty()) r.stop_reason = "maximum iterations reached";
  r.energy = energy;
  r.max_force = maxPointForce(g);
  return r;
}

}  // namespace cortex::detail
