// Builds the plain-data Frame that writers receive from the current System.
#pragma once

#include "sim/frame.hpp"
#include "sim/system.hpp"

namespace cortex {

// Not const: in runs where membranes and filaments interact, the contact forces are
// evaluated (the force field's terms cache their geometry).
Frame makeFrame(System& system);

}  // namespace cortex
