// Where proteins can bind, as the chemistry needs it after each minimization: the pairs
// of sites within a linker's or motor's distance range, and the sites where Arp2/3 may
// branch, each grouped by the compartment whose copies the binding consumes.
//
// Memory is linear in the number of sites, whatever the number of pairs (dense networks
// have tens to hundreds of partners per site): the pairs are counted, not listed. Each
// site keeps the number of its partners among the sites after it (sites sorted by cell of
// a cell list, cells of edge r_max), which files every unordered pair once, under its
// first site's compartment; picking the k-th pair of a compartment finds its first site
// by a binary search over those counts and enumerates that site's partners again.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "chem/compartment_grid.hpp"
#include "filament/filament_network.hpp"

namespace cortex {

// A pair of sites (both entries equal for a branching site).
struct BindingCandidate {
  std::array<Index, 2> filament;
  std::array<std::int32_t, 2> site;
};

class BindingCandidates {
 public:
  BindingCandidates() = default;
  // Site pairs of `kind`/`type` on different filaments at a distance in [rmin, rmax] (nm);
  // only sites whose index is a multiple of `every` count. rmax <= 0: every single site
  // is a candidate by itself (branching).
  BindingCandidates(const FilamentNetwork& net, const CompartmentGrid& grid, BinderKind kind, Index type, double rmin,
                    double rmax, int every);

  std::int64_t count(Index compartment) const;
  // The candidate of the compartment that u in (0, 1) picks uniformly; the compartment
  // must have one.
  BindingCandidate pick(Index compartment, double u) const;

 private:
  struct Site {
    std::uint64_t cell;
    Index filament;
    std::int32_t site;
    Index compartment;
    Vec3 x;
  };
  struct Cell {
    std::uint64_t key;
    std::size_t begin, end;  // its sites
  };
  // Calls f(j) for every partner j > i of site i, in one fixed order; stops early when f
  // returns true.
  template <class F>
  void forEachPartner(std::size_t i, F&& f) const;

  bool pairs_ = false;
  double rmin2_ = 0.0, rmax2_ = 0.0;
  std::vector<Site> sites_;              // sorted by cell
  std::vector<Cell> cells_;              // occupied cells, by key
  std::vector<std::size_t> by_compartment_;  // sites grouped by compartment, in site order
  std::vector<std::int64_t> cumulative_;     // partners of by_compartment_[0..k], within each compartment
  std::vector<std::size_t> start_;           // per compartment, into by_compartment_; size C + 1
};

// Every site of brancher type `brancher` on the filaments of its filament type.
BindingCandidates findBranchSites(const FilamentNetwork& net, const CompartmentGrid& grid, Index brancher);

}  // namespace cortex
