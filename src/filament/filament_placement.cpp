#include "filament/filament_placement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "filament/walls.hpp"

namespace cortex {
namespace {

constexpr int kMaxTries = 100'000;

int monomersOf(const FilamentInit& init, const FilamentType& type) {
  return std::max(1, static_cast<int>(std::lround(init.length / type.monomer_size)));
}

bool fits(const Walls& walls, const Vec3& minus_end, const Vec3& direction, double length) {
  return walls.contains(minus_end) && walls.contains(minus_end + direction * length);
}

void placeRandom(const FilamentInit& init, std::size_t entry, const FilamentType& type, const Walls& walls,
                 const PlacementRegion* inside, RandomStream& random, std::vector<FilamentSeed>& out) {
  const int monomers = monomersOf(init, type);
  const double length = monomers * type.monomer_size;
  Vec3 lo = init.region ? (*init.region)[0] : walls.min;
  Vec3 hi = init.region ? (*init.region)[1] : walls.max;
  if (inside) lo = lo.cwiseMax(inside->min), hi = hi.cwiseMin(inside->max);
  const std::string within =
      inside ? fmt::format("inside membrane \"{}\" (with a margin) and the boundary", init.inside) : "inside the boundary";
  for (int n = 0; n < init.count; ++n) {
    int tries = 0;
    for (;; ++tries) {
      if (tries == kMaxTries || (lo.array() > hi.array()).any() || (inside && length > (hi - lo).norm()))
        throw InputError(fmt::format("filaments.{}: filament {} of {} ({:g} nm) does not fit {} (with a {:g} nm "
                                     "margin) after {} tries; shorten it or widen the region",
                                     entry, n, init.count, length, within, walls.margin, tries));
      Vec3 minus_end;
      for (int k = 0; k < 3; ++k) minus_end[k] = lo[k] + (hi[k] - lo[k]) * random.uniform();
      const Vec3 direction = uniformDirection(random);
      if (fits(walls, minus_end, direction, length) &&
          (!inside || inside->holds(minus_end, minus_end + direction * length))) {
        out.push_back({init.type_index, minus_end, direction, monomers, init.fixed_minus_end, init.clamped_minus_end});
        break;
      }
    }
  }
}

// The first `count` points of a hexagonal lattice with unit spacing in axial
// coordinates: the origin, then ring after ring (Red Blob Games' ring walk).
std::vector<std::array<double, 2>> hexagonalLattice(int count) {
  static constexpr int kSteps[6][2] = {{1, 0}, {1, -1}, {0, -1}, {-1, 0}, {-1, 1}, {0, 1}};
  std::vector<std::array<double, 2>> points;
  auto add = [&](int q, int r) { points.push_back({q + 0.5 * r, std::sqrt(3.0) / 2.0 * r}); };
  if (count > 0) add(0, 0);
  for (int ring = 1; static_cast<int>(points.size()) < count; ++ring) {
    int q = -ring, r = ring;  // ring * kSteps[4]
    for (int side = 0; side < 6; ++side)
      for (int j = 0; j < ring; ++j) {
        add(q, r);
        q += kSteps[side][0];
        r += kSteps[side][1];
      }
  }
  points.resize(static_cast<std::size_t>(std::max(count, 0)));
  return points;
}

void placeBundle(const FilamentInit& init, std::size_t entry, const FilamentType& type, const Walls& walls,
                 std::vector<FilamentSeed>& out) {
  const int monomers = monomersOf(init, type);
  const double length = monomers * type.monomer_size;
  const Vec3 axis = init.direction.normalized();
  const Vec3 e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  const auto lattice = hexagonalLattice(init.count);
  for (std::size_t n = 0; n < lattice.size(); ++n) {
    const Vec3 point = init.center + init.spacing * (lattice[n][0] * e1 + lattice[n][1] * e2);
    const Vec3 direction = init.mixed_polarity && n % 2 == 1 ? Vec3(-axis) : axis;
    const Vec3 minus_end = point - direction * (length / 2);
    if (!fits(walls, minus_end, direction, length))
      throw InputError(fmt::format("filaments.{}: bundle filament {} of {} (lattice point [{:g}, {:g}, {:g}] nm, "
                                   "{:g} nm long) does not fit inside the boundary; move center, or reduce "
                                   "count, spacing or length",
                                   entry, n, init.count, point.x(), point.y(), point.z(), length));
    out.push_back({init.type_index, minus_end, direction, monomers, init.fixed_minus_end, init.clamped_minus_end});
  }
}

}  // namespace

double placementMargin(const FilamentConfig& config) {
  return config.boundary ? 2.0 * config.boundary->screening_length : 0.0;
}

std::vector<FilamentSeed> placeFilaments(const FilamentConfig& config, const Vec3& box_min, const Vec3& box_max,
                                         RandomStream& random,
                                         const std::vector<std::optional<PlacementRegion>>& regions) {
  const Walls walls = wallsOf(config, box_min, box_max, placementMargin(config));
  std::vector<FilamentSeed> seeds;
  for (std::size_t i = 0; i < config.initial.size(); ++i) {
    const FilamentInit& init = config.initial[i];
    const FilamentType& type = config.types.at(static_cast<std::size_t>(init.type_index));
    if (init.placement == FilamentInit::Placement::kBundle)
      placeBundle(init, i, type, walls, seeds);
    else
      placeRandom(init, i, type, walls, i < regions.size() && regions[i] ? &*regions[i] : nullptr, random, seeds);
  }
  return seeds;
}

}  // namespace cortex
