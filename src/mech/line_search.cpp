#include "mech/line_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cortex {
namespace {

struct Sample {
  double a, f, s;  // step, value, directional derivative
};

// Minimizer of the cubic through two samples, kept inside the middle 80% of [lo, hi].
double interpolate(const Sample& lo, const Sample& hi) {
  const double left = std::min(lo.a, hi.a), right = std::max(lo.a, hi.a);
  const double margin = 0.1 * (right - left);
  double a = 0.5 * (lo.a + hi.a);
  if (std::isfinite(hi.f)) {
    const double d1 = lo.s + hi.s - 3.0 * (lo.f - hi.f) / (lo.a - hi.a);
    const double disc = d1 * d1 - lo.s * hi.s;
    if (disc >= 0.0) {
      const double d2 = std::copysign(std::sqrt(disc), hi.a - lo.a);
      const double cubic = hi.a - (hi.a - lo.a) * (hi.s + d2 - d1) / (hi.s - lo.s + 2.0 * d2);
      if (std::isfinite(cubic)) a = cubic;
    }
  }
  return std::clamp(a, left + margin, right - margin);
}

}  // namespace

LineSearchResult wolfeLineSearch(Objective& f, const Eigen::VectorXd& x, double f0, double slope0,
                                 const Eigen::VectorXd& d, double initial_step, double max_step,
                                 const LineSearchParams& p, Eigen::VectorXd& x_new,
                                 Eigen::VectorXd& g_new) {
  int evaluations = 0;
  const double roundoff = 1e-12 * std::abs(f0);
  auto evaluate = [&](double a) {
    ++evaluations;
    x_new = x + a * d;
    const double value = f.valueAndGradient(x_new, g_new);
    const bool finite = std::isfinite(value) && g_new.allFinite();
    return Sample{a, finite ? value : std::numeric_limits<double>::infinity(),
                  finite ? g_new.dot(d) : std::numeric_limits<double>::infinity()};
  };
  auto armijo = [&](const Sample& s) { return s.f <= f0 + p.c1 * s.a * slope0; };
  auto curvature = [&](const Sample& s) { return std::abs(s.s) <= -p.c2 * slope0; };
  // Hager-Zhang: once f cannot resolve the decrease, trust the slope alone.
  auto approximate = [&](const Sample& s) {
    return std::abs(s.f - f0) <= roundoff && s.s >= p.c2 * slope0 && s.s <= -p.c2 * slope0;
  };
  auto accept = [&](const Sample& s) { return LineSearchResult{true, s.a, s.f}; };

  Sample prev{0.0, f0, slope0};
  Sample cur = evaluate(std::min(initial_step, max_step));
  Sample lo = prev, hi = cur;
  bool bracketed = false;
  while (!bracketed && evaluations < p.max_evaluations) {
    if ((armijo(cur) && curvature(cur)) || approximate(cur)) return accept(cur);
    if (!armijo(cur) || (evaluations > 1 && cur.f >= prev.f)) {
      lo = prev, hi = cur, bracketed = true;
    } else if (cur.s >= 0.0) {
      lo = cur, hi = prev, bracketed = true;
    } else if (cur.a >= max_step) {
      return accept(cur);  // still descending at the largest allowed step
    } else {
      prev = cur;
      cur = evaluate(std::min(2.0 * cur.a, max_step));
    }
  }
  while (evaluations < p.max_evaluations) {
    const Sample trial = evaluate(interpolate(lo, hi));
    if (!armijo(trial) || trial.f >= lo.f) {
      if (approximate(trial)) return accept(trial);
      hi = trial;
    } else {
      if (curvature(trial)) return accept(trial);
      if (trial.s * (hi.a - lo.a) >= 0.0) hi = lo;
      lo = trial;
    }
    if (std::abs(hi.a - lo.a) <= 1e-14 * std::max(1.0, lo.a)) break;
  }
  // No Wolfe point found: settle for the best decrease seen, if any.
  if (lo.a > 0.0 && lo.f < f0) {
    x_new = x + lo.a * d;
    const double value = f.valueAndGradient(x_new, g_new);
    return {true, lo.a, value};
  }
  return {false, 0.0, f0};
}

}  // namespace cortex
