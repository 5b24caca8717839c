#include "io/resolvable_forces.hpp"

namespace cortex {

void requireResolvableForces(const ConfigReader& r, const std::string& key, double force_scale,
                             const std::string& scale_formula, double tolerance) {
  const std::string problem =
      unresolvableForces(force_scale, scale_formula, tolerance, "[mechanics] force_tolerance");
  if (!problem.empty()) r.fail(key, problem);
}

}  // namespace cortex
