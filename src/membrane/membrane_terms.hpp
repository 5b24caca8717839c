// The energy terms of a membrane, from its own parameters: the one place a new membrane
// term is registered.
#pragma once

#include "mech/force_field.hpp"
#include "membrane/membrane.hpp"

namespace cortex {

// Adds every term the membrane's parameters ask for. Terms whose modulus is zero at all
// times are left out: they cost time and add nothing.
void addMembraneTerms(Membrane& membrane, ForceField& force_field);

}  // namespace cortex
