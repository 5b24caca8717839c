// Turns a membrane's config into a Membrane: generates or loads its mesh, fixes the
// boundary of open membranes, or restores mesh and reference state from a checkpoint.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sim/run_config.hpp"
#include "sim/system_state.hpp"

namespace cortex {

std::unique_ptr<Membrane> buildMembrane(const MembraneConfig& config, const std::string& source,
                                        const MembraneState* restored = nullptr);

// The initial mesh a config describes (generated or read from file), validated.
TriangleSoup initialMesh(const MembraneConfig& config);

// The state a checkpoint stores.
MembraneState membraneState(const Membrane& membrane);

// The membrane a key such as a species' `inside` names, which must be closed (the config
// reader refused planes; a loaded mesh may still be open). InputError "KEY: ..." else.
const Membrane& closedMembrane(const std::vector<std::unique_ptr<Membrane>>& membranes, const std::string& name,
                               const std::string& key);

}  // namespace cortex
