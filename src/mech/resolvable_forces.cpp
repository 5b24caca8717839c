#include "mech/resolvable_forces.hpp"

#include <fmt/format.h>

namespace cortex {

std::string unresolvableForces(double force_scale, const std::string& scale_formula, double tolerance,
                               const std::string& tolerance_source) {
  if (!(force_scale > kMaxForceScaleOverTolerance * tolerance)) return {};
  return fmt::format("makes forces of order {} = {:.3g} pN, over {:g} x the force tolerance ({:.3g} pN, {}): no "
                     "relaxation can resolve them to it in double precision (is it in the documented units?)",
                     scale_formula, force_scale, kMaxForceScaleOverTolerance, tolerance, tolerance_source);
}

}  // namespace cortex
