#include "filament/binding_candidates.hpp"

#include <algorithm>
#include <cmath>

namespace cortex {
namespace {

// Counting sort of (compartment, candidate) by compartment, keeping their order within one.
BindingCandidates byCompartment(const std::vector<std::pair<Index, BindingCandidate>>& items,
                                const CompartmentGrid& grid) {
  BindingCandidates out;
  out.start.assign(grid.count() + 1, 0);
  for (const auto& [comp, _] : items) ++out.start[comp + 1];
  for (Index k = 0; k < grid.count(); ++k) out.start[k + 1] += out.start[k];
  out.list.resize(items.size());
  std::vector<Index> fill(out.start.begin(), out.start.end() - 1);
  for (const auto& [comp, cand] : items) out.list[fill[comp]++] = cand;
  return out;
}

}  // namespace

// Site pairs on different filaments at a distance in [rmin, rmax], found through a cell
// list of the sites (cells of edge rmax, sorted by cell key) and grouped by the
// compartment of the pair's first site (where the bound protein's reactions will fire).
// Only sites whose index is a multiple of `every` may bind.
BindingCandidates findSitePairs(const FilamentNetwork& net, const CompartmentGrid& grid, BinderKind kind, Index type,
                                double rmin, double rmax, int every) {
  struct Site {
    std::uint64_t cell;
    Index filament;
    std::int32_t site;
    Index compartment;
    Vec3 x;
  };
  const double inv = 1.0 / rmax;
  auto cellOf = [&](const Vec3& x) {
    // 21 bits per axis, offset so that negative coordinates stay ordered.
    auto axis = [&](double v) { return static_cast<std::uint64_t>(std::floor(v * inv) + (1 << 20)) & 0x1FFFFF; };
    return axis(x.x()) << 42 | axis(x.y()) << 21 | axis(x.z());
  };
  std::vector<Site> sites;
  const auto& fils = net.filaments();
  const double sp = net.spacing(kind, type);
  for (Index f = 0; f < static_cast<Index>(fils.size()); ++f) {
    const Filament& fil = fils[f];
    for (Index c = 0; c < fil.numCylinders(); ++c) {
      const auto [first, last] = net.sitesOnCylinder(kind, type, f, c);
      const double lo = static_cast<double>(fil.lattice[c]), span = static_cast<double>(fil.lattice[c + 1]) - lo;
      for (std::int64_t j = first; j <= last; ++j) {
        if (j % every != 0) continue;
        const double w = ((static_cast<double>(j) + 0.5) * sp - lo) / span;
        const Vec3 x = (1.0 - w) * fil.beads[c] + w * fil.beads[c + 1];
        sites.push_back({cellOf(x), f, static_cast<std::int32_t>(j), grid.locate(x), x});
      }
    }
  }
  std::stable_sort(sites.begin(), sites.end(), [](const Site& a, const Site& b) { return a.cell < b.cell; });
  // Occupied cells as ranges of the sorted sites; each unordered pair of neighbouring
  // cells is visited once (the second cell's key not below the first's).
  struct Cell {
    std::uint64_t key;
    std::size_t begin, end;
  };
  std::vector<Cell> cells;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    if (cells.empty() || cells.back().key != sites[i].cell) cells.push_back({sites[i].cell, i, i});
    cells.back().end = i + 1;
  }
  std::vector<std::pair<Index, BindingCandidate>> found;
  const double rmin2 = rmin * rmin, rmax2 = rmax * rmax;
  for (const Cell& a : cells) {
    const std::uint64_t ci = a.key >> 42, cj = a.key >> 21 & 0x1FFFFF, ck = a.key & 0x1FFFFF;
    for (std::uint64_t di = 0; di < 3; ++di)
      for (std::uint64_t dj = 0; dj < 3; ++dj)
        for (std::uint64_t dk = 0; dk < 3; ++dk) {
          const std::uint64_t key = (ci + di - 1) << 42 | (cj + dj - 1) << 21 | (ck + dk - 1);
          if (key < a.key) continue;
          const auto b = std::lower_bound(cells.begin(), cells.end(), key,
                                          [](const Cell& c, std::uint64_t k) { return c.key < k; });
          if (b == cells.end() || b->key != key) continue;
          for (std::size_t i = a.begin; i < a.end; ++i)
            for (std::size_t j = b->key == a.key ? i + 1 : b->begin; j < b->end; ++j) {
              const Site &p = sites[i], &q = sites[j];
              if (p.filament == q.filament) continue;  // never on one filament
              const double d2 = (q.x - p.x).squaredNorm();
              if (d2 < rmin2 || d2 > rmax2) continue;
              found.push_back({p.compartment, {{p.filament, q.filament}, {p.site, q.site}}});
            }
        }
  }
  return byCompartment(found, grid);
}

BindingCandidates findBranchSites(const FilamentNetwork& net, const CompartmentGrid& grid, Index brancher) {
  std::vector<std::pair<Index, BindingCandidate>> sites;
  const auto& fils = net.filaments();
  for (Index f = 0; f < static_cast<Index>(fils.size()); ++f) {
    if (fils[f].type != net.config().branchers[brancher].filament_type_index) continue;
    for (Index cyl = 0; cyl < fils[f].numCylinders(); ++cyl) {
      const auto [first, last] = net.sitesOnCylinder(BinderKind::kBrancher, brancher, f, cyl);
      for (std::int64_t s = first; s <= last; ++s)
        sites.push_back({grid.locate(net.sitePosition(BinderKind::kBrancher, brancher, f, s)),
                         {{f, f}, {static_cast<std::int32_t>(s), static_cast<std::int32_t>(s)}}});
    }
  }
  return byCompartment(sites, grid);
}

}  // namespace cortex
