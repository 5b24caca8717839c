// Turns a membrane's config into a Membrane: generates or loads its mesh, fixes the
// boundary of open membranes, or restores mesh and reference state from a checkpoint.
#pragma once

#include <memory>
#include <optional>

#include "sim/run_config.hpp"
#include "membrane/membrane.hpp"

namespace cortex {

// The part of a membrane's state that a checkpoint stores.
struct MembraneState {
  TriangleSoup mesh;
  std::vector<char> fixed;
  MembraneMaterial material;
  RemeshStats remesh_totals;
  // The remesher's settings as resolved at the start (a loaded mesh's defaults come from
  // its original edge lengths, which remeshing changes).
  std::optional<RemeshSettings> remeshing;
};

std::unique_ptr<Membrane> buildMembrane(const MembraneConfig& config, const std::string& source,
                                        const std::optional<MembraneState>& restored = std::nullopt);

// The initial mesh a config describes (generated or read from file), validated.
TriangleSoup initialMesh(const MembraneConfig& config);

}  // namespace cortex
