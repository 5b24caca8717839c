#include "mech/minimizer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.hpp"

namespace cortex {

MinimizationResult minimize(Objective& f, Eigen::VectorXd& x, const MinimizerSettings& settings) {
  // kAuto here is a body without a shape relaxation of its own: conjugate gradients.
  return settings.kind == MinimizerKind::kLbfgs ? detail::lbfgs(f, x, settings)
                                                : detail::conjugateGradient(f, x, settings);
}

namespace detail {

double maxAbs(const Eigen::VectorXd& v) {
  if (!v.allFinite()) return std::numeric_limits<double>::infinity();
  return v.size() ? v.cwiseAbs().maxCoeff() : 0.0;
}

double maxPointForce(const Eigen::VectorXd& g) {
  if (g.size() % 3 != 0)
    throw std::invalid_argument(fmt::format("a gradient of {} entries is not x, y, z per point", g.size()));
  if (!g.allFinite()) return std::numeric_limits<double>::infinity();
  const Eigen::Index points = g.size() / 3;
  const auto triples = Eigen::Map<const Eigen::Matrix3Xd>(g.data(), 3, points);
  return points ? std::sqrt(triples.colwise().squaredNorm().maxCoeff()) : 0.0;
}

void checkFinite(double energy, const Eigen::VectorXd& gradient, const char* where) {
  if (!std::isfinite(energy))
    throw RunError(fmt::format("energy is {} {}: check parameters for impossible values", energy, where));
  if (!gradient.allFinite())
    throw RunError(fmt::format("forces are not finite {} (degenerate geometry?)", where));
}

void checkBounded(double energy, const Eigen::VectorXd& x, const Eigen::VectorXd& start) {
  // A relaxation moves a structure by a fraction of its size; travelling a hundred
  // times its size means the energy is unbounded below (e.g. negative tension with no
  // area elasticity) and the minimizer would otherwise run to max_iterations.
  const double extent = start.size() ? start.maxCoeff() - start.minCoeff() : 0.0;
  const double travelled = maxAbs(x - start);
  if (travelled > 100.0 * extent + 1e4 || energy < -1e30 || !x.allFinite())
    throw RunError(fmt::format(
        "energy minimization diverged (energy {:.6g} pN·nm, a coordinate travelled {:.3g} nm "
        "from where the minimization began): the energy is unbounded below; check the signs "
        "and sizes of tension and moduli",
        energy, travelled));
}

}  // namespace detail
}  // namespace cortex
