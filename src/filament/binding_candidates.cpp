#include "filament/binding_candidates.hpp"

#include <algorithm>
#include <cmath>

namespace cortex {
namespace {

// 21 bits per axis of a cell index, offset so that negative coordinates stay ordered.
std::uint64_t cellKey(const Vec3& x, double inverse_edge) {
  auto axis = [&](double v) {
    return static_cast<std::uint64_t>(std::floor(v * inverse_edge) + (1 << 20)) & 0x1FFFFF;
  };
  return axis(x.x()) << 42 | axis(x.y()) << 21 | axis(x.z());
}

}  // namespace

BindingCandidates::BindingCandidates(const FilamentNetwork& net, const CompartmentGrid& grid, BinderKind kind,
                                     Index type, double rmin, double rmax, int every)
    : pairs_(rmax > 0.0), rmin2_(rmin * rmin), rmax2_(rmax * rmax) {
  const double inverse_edge = pairs_ ? 1.0 / rmax : 0.0;
  const auto& fils = net.filaments();
  const double sp = net.spacing(kind, type);
  for (Index f = 0; f < static_cast<Index>(fils.size()); ++f) {
    const Filament& fil = fils[f];
    if (kind == BinderKind::kBrancher && fil.type != net.config().branchers[type].filament_type_index) continue;
    for (Index c = 0; c < fil.numCylinders(); ++c) {
      const auto [first, last] = net.sitesOnCylinder(kind, type, f, c);
      const double lo = static_cast<double>(fil.lattice[c]), span = static_cast<double>(fil.lattice[c + 1]) - lo;
      for (std::int64_t j = first; j <= last; ++j) {
        if (j % every != 0) continue;
        const double w = ((static_cast<double>(j) + 0.5) * sp - lo) / span;
        const Vec3 x = (1.0 - w) * fil.beads[c] + w * fil.beads[c + 1];
        sites_.push_back({pairs_ ? cellKey(x, inverse_edge) : 0, f, static_cast<std::int32_t>(j), grid.locate(x), x});
      }
    }
  }
  std::stable_sort(sites_.begin(), sites_.end(), [](const Site& a, const Site& b) { return a.cell < b.cell; });
  for (std::size_t i = 0; i < sites_.size(); ++i) {
    if (cells_.empty() || cells_.back().key != sites_[i].cell) cells_.push_back({sites_[i].cell, i, i});
    cells_.back().end = i + 1;
  }
  // Sites grouped by compartment (counting sort, keeping site order), each with its
  // partners' count accumulated within its compartment.
  const Index C = grid.count();
  start_.assign(static_cast<std::size_t>(C) + 1, 0);
  for (const Site& s : sites_) ++start_[s.compartment + 1];
  for (Index c = 0; c < C; ++c) start_[c + 1] += start_[c];
  by_compartment_.resize(sites_.size());
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < sites_.size(); ++i) by_compartment_[fill[sites_[i].compartment]++] = i;
  cumulative_.resize(sites_.size());
  for (Index c = 0; c < C; ++c) {
    std::int64_t sum = 0;
    for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) {
      std::int64_t partners = 0;
      if (pairs_)
        forEachPartner(by_compartment_[k], [&](std::size_t) { return ++partners, false; });
      else
        partners = 1;
      cumulative_[k] = sum += partners;
    }
  }
}

template <class F>
void BindingCandidates::forEachPartner(std::size_t i, F&& f) const {
  const Site& p = sites_[i];
  const std::uint64_t ci = p.cell >> 42, cj = p.cell >> 21 & 0x1FFFFF, ck = p.cell & 0x1FFFFF;
  // The 27 cells around, those not before p's own (so each unordered pair is met once).
  for (std::uint64_t di = 0; di < 3; ++di)
    for (std::uint64_t dj = 0; dj < 3; ++dj)
      for (std::uint64_t dk = 0; dk < 3; ++dk) {
        const std::uint64_t key = (ci + di - 1) << 42 | (cj + dj - 1) << 21 | (ck + dk - 1);
        if (key < p.cell) continue;
        const auto b = std::lower_bound(cells_.begin(), cells_.end(), key,
                                        [](const Cell& c, std::uint64_t k) { return c.key < k; });
        if (b == cells_.end() || b->key != key) continue;
        for (std::size_t j = key == p.cell ? i + 1 : b->begin; j < b->end; ++j) {
          const Site& q = sites_[j];
          if (p.filament == q.filament) continue;  // never on one filament
          const double d2 = (q.x - p.x).squaredNorm();
          if (d2 < rmin2_ || d2 > rmax2_) continue;
          if (f(j)) return;
        }
      }
}

std::int64_t BindingCandidates::count(Index c) const {
  if (start_.empty() || start_[c] == start_[c + 1]) return 0;
  return cumulative_[start_[c + 1] - 1];
}

BindingCandidate BindingCandidates::pick(Index c, double u) const {
  const std::int64_t n = count(c);
  std::int64_t k = std::min<std::int64_t>(n - 1, static_cast<std::int64_t>(u * static_cast<double>(n)));
  // The site holding the k-th pair: the first whose cumulative count exceeds k.
  const auto first = cumulative_.begin() + static_cast<std::ptrdiff_t>(start_[c]);
  const auto at = std::upper_bound(first, cumulative_.begin() + static_cast<std::ptrdiff_t>(start_[c + 1]), k);
  if (at != first) k -= *(at - 1);
  const std::size_t i = by_compartment_[static_cast<std::size_t>(at - cumulative_.begin())];
  const Site& p = sites_[i];
  if (!pairs_) return {{p.filament, p.filament}, {p.site, p.site}};
  std::size_t partner = i;
  forEachPartner(i, [&](std::size_t j) {
    partner = j;
    return k-- == 0;
  });
  const Site& q = sites_[partner];
  return {{p.filament, q.filament}, {p.site, q.site}};
}

BindingCandidates findBranchSites(const FilamentNetwork& net, const CompartmentGrid& grid, Index brancher) {
  return BindingCandidates(net, grid, BinderKind::kBrancher, brancher, 0.0, 0.0, 1);
}

}  // namespace cortex
