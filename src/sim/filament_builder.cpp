#include "sim/filament_builder.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/random.hpp"
#include "interact/inside_membrane.hpp"
#include "sim/membrane_builder.hpp"

namespace cortex {
namespace {

// A checkpoint is input too: refuse anything the network could not have produced with
// this config (types, monotone lattices, finite beads, sites on their filaments, one
// protein per site, capped daughters), so a damaged file stops with exit 2, not a crash.
void checkRestored(const FilamentConfig& config, const FilamentState& s) {
  auto bad = [](const std::string& what) {
    return InputError("checkpoint.h5: /filaments: " + what + " (damaged file, or a config with fewer types?)");
  };
  for (std::size_t i = 0; i < s.filaments.size(); ++i) {
    const Filament& f = s.filaments[i];
    if (f.type < 0 || static_cast<std::size_t>(f.type) >= config.types.size())
      throw bad(fmt::format("filament {} has type {}", i, f.type));
    for (std::size_t b = 0; b < f.beads.size(); ++b) {
      if (!f.beads[b].allFinite()) throw bad(fmt::format("filament {} has a non-finite bead", i));
      if (b > 0 && f.lattice[b] <= f.lattice[b - 1]) throw bad(fmt::format("filament {} has an empty cylinder", i));
    }
  }
  FilamentNetwork probe(config);
  for (const Filament& f : s.filaments) probe.addFilament(f);
  auto checkSite = [&](BinderKind kind, Index type, Index filament, std::int64_t site, const char* what) {
    if (!probe.siteExists(kind, type, filament, site))
      throw bad(fmt::format("a {} sits on site {} that filament {} does not cover", what, site, filament));
  };
  for (BinderKind kind : {BinderKind::kLinker, BinderKind::kMotor}) {
    const bool linker = kind == BinderKind::kLinker;
    const auto& bound = linker ? s.linkers : s.motors;
    const std::size_t types = linker ? config.linkers.size() : config.motors.size();
    const char* what = linker ? "linker" : "motor";
    for (const Binding& b : bound) {
      if (b.type < 0 || static_cast<std::size_t>(b.type) >= types) throw bad(fmt::format("a {} has type {}", what, b.type));
      if (b.filament[0] == b.filament[1]) throw bad(fmt::format("a {} binds one filament twice", what));
      if (!std::isfinite(b.rest_length) || b.rest_length < 0) throw bad(fmt::format("a {} has a bad rest length", what));
      for (int e = 0; e < 2; ++e) {
        checkSite(kind, b.type, b.filament[e], b.site[e], what);
        if (probe.occupied(kind, b.type, b.filament[e], b.site[e]))
          throw bad(fmt::format("two {}s share site {} of filament {}", what, b.site[e], b.filament[e]));
      }
      probe.bind(kind, b);
    }
  }
  for (const Branch& b : s.branches) {
    if (b.type < 0 || static_cast<std::size_t>(b.type) >= config.branchers.size())
      throw bad(fmt::format("a branch has type {}", b.type));
    if (b.mother == b.daughter || !s.filaments[b.daughter].minus_capped)
      throw bad(fmt::format("branch daughter {} is not a capped filament", b.daughter));
    checkSite(BinderKind::kBrancher, b.type, b.mother, b.site, "branch");
  }
}

}  // namespace

std::unique_ptr<FilamentNetwork> buildFilamentNetwork(const FilamentConfig& config, const Vec3& box_min,
                                                      const Vec3& box_max, std::uint64_t seed,
                                                      const FilamentState* restored,
                                                      const std::vector<std::optional<PlacementRegion>>& regions) {
  auto network = std::make_unique<FilamentNetwork>(config);
  if (restored) {
    checkRestored(config, *restored);
    network->restore(restored->filaments, restored->linkers, restored->motors, restored->branches);
    network->events() = restored->events;
    return network;
  }
  RandomStream random(seed, StreamId::kFilamentPlacement);
  for (const FilamentSeed& s : placeFilaments(config, box_min, box_max, random, regions)) {
    const FilamentType& t = config.types[s.type];
    Filament f = makeStraightFilament(s.type, s.minus_end, s.direction, s.monomers, t.cylinder_monomers, t.monomer_size);
    f.minus_anchored = s.fixed_minus_end;
    f.minus_clamped = s.clamped_minus_end;
    network->addFilament(std::move(f));
  }
  return network;
}

std::vector<std::optional<PlacementRegion>> placementRegions(const FilamentConfig& config,
                                                             const std::vector<std::unique_ptr<Membrane>>& membranes,
                                                             double margin) {
  std::vector<std::optional<PlacementRegion>> regions(config.initial.size());
  for (std::size_t i = 0; i < config.initial.size(); ++i) {
    const std::string& name = config.initial[i].inside;
    if (name.empty()) continue;
    const SurfaceMesh& mesh = closedMembrane(membranes, name, fmt::format("filaments.{}.inside", i)).mesh();
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Vec3& x : mesh.positions()) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    regions[i] = PlacementRegion{lo, hi, [&mesh, margin](const Vec3& a, const Vec3& b) {
                                   return segmentInside(mesh, a, b, margin);
                                 }};
  }
  return regions;
}

FilamentState filamentState(const FilamentNetwork& network) {
  return {network.filaments(), network.linkers(), network.motors(), network.branches(), network.events()};
}

}  // namespace cortex
