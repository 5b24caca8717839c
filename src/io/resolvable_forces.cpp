#include "io/resolvable_forces.hpp"

#include <fmt/format.h>

namespace cortex {

void requireResolvableForces(const ConfigReader& r, const std::string& key, double force_scale,
                             const std::string& scale_formula, double tolerance) {
  if (!(force_scale > kMaxForceScaleOverTolerance * tolerance)) return;
  r.fail(key, fmt::format("makes forces of order {} = {:.3g} pN, over {:g} x the force tolerance ({:g} pN, "
                          "[mechanics] force_tolerance): no relaxation can resolve them to it in double "
                          "precision (is it in the documented units?)",
                          scale_formula, force_scale, kMaxForceScaleOverTolerance, tolerance));
}

}  // namespace cortex
