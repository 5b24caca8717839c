#include "mech/minimizer.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"

namespace cortex {

MinimizationResult minimize(Objective& f, Eigen::VectorXd& x, const MinimizerSettings& settings) {
  return settings.kind == MinimizerKind::kLbfgs ? detail::lbfgs(f, x, settings)
                                                : detail::conjugateGradient(f, x, settings);
}

namespace detail {

double maxAbs(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

void checkFinite(double energy, const Eigen::VectorXd& gradient, const char* where) {
  if (!std::isfinite(energy))
    throw RunError(fmt::format("energy is {} {}: check parameters for impossible values", energy, where));
  if (!gradient.allFinite())
    throw RunError(fmt::format("forces are not finite {} (degenerate geometry?)", where));
}

void checkBounded(double energy, const Eigen::VectorXd& x) {
  // Far beyond any cell: the energy is unbounded below (e.g. negative tension with no
  // area elasticity) and the minimizer would never stop.
  constexpr double kRunaway = 1e9;  // nm
  if (maxAbs(x) > kRunaway || energy < -1e30)
    throw RunError(fmt::format(
        "energy minimization diverged (energy {:.6g} pN·nm, a coordinate reached {:.3g} nm): "
        "the energy is unbounded below; check the signs and sizes of tension and moduli",
        energy, maxAbs(x)));
}

}  // namespace detail
}  // namespace cortex
