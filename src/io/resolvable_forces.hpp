// The config reader's side of mech/resolvable_forces.hpp: a stiffness whose force scale no
// relaxation can resolve to the force tolerance is refused, naming its key.
#pragma once

#include <string>

#include "io/config_reader.hpp"
#include "mech/resolvable_forces.hpp"

namespace cortex {

// Fails `key` of r when force_scale (pN; `scale_formula` says how it was formed)
// exceeds kMaxForceScaleOverTolerance × tolerance ([mechanics] force_tolerance, pN).
void requireResolvableForces(const ConfigReader& r, const std::string& key, double force_scale,
                             const std::string& scale_formula, double tolerance);

}  // namespace cortex
