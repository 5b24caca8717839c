// The check that no filament passes through a membrane: every cylinder (segment between
// consecutive beads) against every triangle near it. Run after each relaxation (which
// remeshes within) and when a run starts; what it finds is an error, never corrected
// silently (docs/coupling.md).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "filament/filament_network.hpp"
#include "membrane/membrane.hpp"

namespace cortex {

struct MembraneCrossing {
  Index filament, cylinder, face;
  std::string describe(const Membrane& membrane) const;
};

// The first crossing in (filament, cylinder, triangle) order, if any.
std::optional<MembraneCrossing> findMembraneCrossing(const Membrane& membrane, const FilamentNetwork& network);

// Whether the segment [p, q] meets a triangle of the membrane (every triangle tried: for
// a rare event, such as placing a nucleus).
bool segmentMeetsMembrane(const Membrane& membrane, const Vec3& p, const Vec3& q);

// Whether two membranes pass through each other: some edge of one meets a triangle of the
// other (two meshes that intersect always have such an edge, in one direction or the
// other). Membranes do not interact, so cortex refuses them at the start and stops a run
// where they come to meet; it says where.
std::optional<std::string> findMembranesCrossing(const Membrane& a, const Membrane& b);

struct MembranesCrossing {
  const Membrane *a, *b;
  std::string where;  // findMembranesCrossing's description
};
// The first pair of `membranes` (in their order) passing through each other, if any.
std::optional<MembranesCrossing> findCrossingMembranes(const std::vector<std::unique_ptr<Membrane>>& membranes);

}  // namespace cortex
