// Line search satisfying the strong Wolfe conditions (Nocedal & Wright 2006, alg. 3.5
// and 3.6) with cubic interpolation, plus the approximate Wolfe test of Hager & Zhang
// (2005) so that it still terminates when energy differences sink below round-off.
#pragma once

#include <Eigen/Core>

#include "mech/objective.hpp"

namespace cortex {

struct LineSearchParams {
  double c1 = 1e-4;   // sufficient decrease
  double c2 = 0.9;    // curvature (0.1 for conjugate gradients)
  int max_evaluations = 40;
};

struct LineSearchResult {
  bool ok = false;
  double step = 0.0;
  double value = 0.0;
};

// Searches x + a d for a > 0, given f0 = f(x) and slope0 = grad f(x).d < 0, starting at
// a = initial_step and never exceeding max_step. On success x_new and g_new hold the
// accepted point and its gradient.
LineSearchResult wolfeLineSearch(Objective& f, const Eigen::VectorXd& x, double f0, double slope0,
                                 const Eigen::VectorXd& d, double initial_step, double max_step,
                                 const LineSearchParams& params, Eigen::VectorXd& x_new,
                                 Eigen::VectorXd& g_new);

}  // namespace cortex
