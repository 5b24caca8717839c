// Builds the plain-data Frame that writers receive from the current System.
#pragma once

#include "sim/frame.hpp"
#include "sim/system.hpp"

namespace cortex {

Frame makeFrame(const System& system);

}  // namespace cortex
