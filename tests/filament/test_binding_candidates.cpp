// The binding-pair search against brute force: every pair of sites on different filaments
// within the distance range, counted once under its first site's compartment, and picked
// exactly once when every slice of (0, 1) is drawn.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "filament/binding_candidates.hpp"

namespace cortex {
namespace {

TEST(BindingCandidates, SitePairsMatchBruteForce) {
  FilamentConfig config;
  FilamentType t;
  config.types = {t};
  LinkerType l;
  config.linkers = {l};
  MotorType m;
  config.motors = {m};
  FilamentNetwork net(config);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 80; ++i) {
    const Vec3 dir = Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized();
    Filament f = makeStraightFilament(0, Vec3(u(rng), u(rng), u(rng)) * 400.0, dir, 20 + static_cast<int>(u(rng) * 150),
                                      40, 2.7);
    // Shift some lattices negative, as minus-end growth does.
    if (i % 3 == 0)
      for (auto& c : f.lattice) c -= 37;
    net.addFilament(std::move(f));
  }
  CompartmentGrid grid;
  grid.size = 300.0;
  grid.shape = {2, 2, 2};
  struct Case {
    BinderKind kind;
    double rmin, rmax;
    int every;
  };
  for (const Case& c : {Case{BinderKind::kLinker, 30.0, 40.0, 1}, Case{BinderKind::kMotor, 175.0, 225.0, 5}}) {
    const BindingCandidates found(net, grid, c.kind, 0, c.rmin, c.rmax, c.every);
    std::set<std::array<std::int64_t, 5>> got, expected;
    for (Index comp = 0; comp < grid.count(); ++comp)
      for (std::int64_t k = 0; k < found.count(comp); ++k) {
        // The k-th pair: u in the middle of its 1/n slice.
        const BindingCandidate p = found.pick(comp, (static_cast<double>(k) + 0.5) / static_cast<double>(found.count(comp)));
        // Filed under the first site's compartment.
        EXPECT_EQ(grid.locate(net.sitePosition(c.kind, 0, p.filament[0], p.site[0])), comp);
        std::array<std::int64_t, 5> key{p.filament[0], p.site[0], p.filament[1], p.site[1], 0};
        if (key[0] > key[2]) key = {p.filament[1], p.site[1], p.filament[0], p.site[0], 0};
        EXPECT_TRUE(got.insert(key).second) << "pair listed twice";
      }
    // Brute force over all sites of all filaments.
    std::vector<std::pair<Index, std::int64_t>> sites;
    for (Index f = 0; f < static_cast<Index>(net.filaments().size()); ++f)
      for (Index cyl = 0; cyl < net.filaments()[f].numCylinders(); ++cyl) {
        const auto [first, last] = net.sitesOnCylinder(c.kind, 0, f, cyl);
        for (std::int64_t s = first; s <= last; ++s)
          if (s % c.every == 0) sites.push_back({f, s});
      }
    for (std::size_t i = 0; i < sites.size(); ++i)
      for (std::size_t j = i + 1; j < sites.size(); ++j) {
        if (sites[i].first == sites[j].first) continue;
        const double d = (net.sitePosition(c.kind, 0, sites[i].first, sites[i].second) -
                          net.sitePosition(c.kind, 0, sites[j].first, sites[j].second))
                             .norm();
        if (d < c.rmin || d > c.rmax) continue;
        std::array<std::int64_t, 5> key{sites[i].first, sites[i].second, sites[j].first, sites[j].second, 0};
        if (key[0] > key[2]) key = {sites[j].first, sites[j].second, sites[i].first, sites[i].second, 0};
        expected.insert(key);
      }
    EXPECT_GT(expected.size(), 50u);
    EXPECT_EQ(got, expected);
  }
}

}  // namespace
}  // namespace cortex
