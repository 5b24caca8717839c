// Where proteins can bind, as the chemistry needs it after each minimization: the pairs
// of sites within a linker's or motor's distance range, and the sites where Arp2/3 may
// branch, each grouped by the compartment whose copies the binding consumes.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "chem/chemistry_model.hpp"
#include "filament/filament_network.hpp"

namespace cortex {

// A pair of sites (both entries equal for a branching site).
struct BindingCandidate {
  std::array<Index, 2> filament;
  std::array<std::int32_t, 2> site;
};

struct BindingCandidates {
  std::vector<Index> start;  // per compartment, into list; size C + 1
  std::vector<BindingCandidate> list;
  Index count(Index c) const { return start[c + 1] - start[c]; }
  // The candidate of compartment c that u in (0, 1) picks uniformly; null if c has none.
  const BindingCandidate* pick(Index c, double u) const {
    const Index n = count(c);
    return n == 0 ? nullptr : &list[start[c] + std::min<Index>(n - 1, static_cast<Index>(u * n))];
  }
};

// Site pairs of `kind`/`type` on different filaments at a distance in [rmin, rmax] (nm),
// each unordered pair once; only sites whose index is a multiple of `every` count.
BindingCandidates findSitePairs(const FilamentNetwork& net, const CompartmentGrid& grid, BinderKind kind, Index type,
                                double rmin, double rmax, int every);
// Every site of brancher type `brancher` on the filaments of its filament type.
BindingCandidates findBranchSites(const FilamentNetwork& net, const CompartmentGrid& grid, Index brancher);

}  // namespace cortex
