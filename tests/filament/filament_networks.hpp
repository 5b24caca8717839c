// Filament networks shared by the filament tests and the gradient test: two types, a
// random tangle with linkers, motors and branches after kOffset dummy beads, and walls.
#pragma once

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "filament/filament_layout.hpp"
#include "filament/filament_params.hpp"

namespace cortex::filtest {

inline constexpr Index kOffset = 4;           // beads of "something else" before the filaments

inline std::vector<FilamentType> testTypes() {
  std::vector<FilamentType> types(2);
  types[0].stretching_stiffness = 100.0;
  types[0].bending_stiffness = 672.0;
  types[0].excluded_volume_stiffness = 10.0;
  types[0].excluded_volume_distance = 9.0;
  types[1].name = "other";
  types[1].stretching_stiffness = 40.0;
  types[1].bending_stiffness = 300.0;
  types[1].excluded_volume_stiffness = 30.0;
  types[1].excluded_volume_distance = 15.0;
  return types;
}

// A tangle of `filaments` random walks of `cylinders` cylinders (~20 nm) in a ~60 nm
// region, with linkers, motors and two branch joints; x holds kOffset dummy beads first.
struct Network {
  FilamentLayout layout;
  std::vector<double> x;
};

inline Vec3 beadOf(const Network& n, Index b) { return Eigen::Map<const Vec3>(n.x.data() + 3 * (kOffset + b)); }

inline Network randomNetwork(unsigned seed, int filaments = 6, int cylinders = 4, double region = 60.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  Network n;
  n.layout.version = seed + 1;
  n.layout.bead_offset = kOffset;
  n.x.assign(3 * kOffset, 0.0);
  for (double& v : n.x) v = 100.0 * u(rng);
  Index bead = 0;
  for (int f = 0; f < filaments; ++f) {
    const Index type = f % 2;
    Vec3 p(region * u(rng), region * u(rng), region * u(rng));
    Vec3 dir = Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    for (int c = 0; c <= cylinders; ++c) {
      n.x.insert(n.x.end(), {p.x(), p.y(), p.z()});
      if (c < cylinders) {
        n.layout.cylinders.push_back({bead + c, bead + c + 1, f, type, 15.0 + 10.0 * u(rng)});
        dir = (dir + 0.5 * Vec3(gauss(rng), gauss(rng), gauss(rng))).normalized();
        p += (18.0 + 6.0 * u(rng)) * dir;
      }
      if (c >= 1 && c < cylinders) n.layout.hinges.push_back({bead + c - 1, bead + c, bead + c + 1, type});
    }
    bead += cylinders + 1;
  }
  n.layout.num_beads = bead;
  const auto& cyl = n.layout.cylinders;
  auto randomPoint = [&](Index c) { return CylinderPoint{cyl[c].bead0, cyl[c].bead1, u(rng)}; };
  auto randomCylinder = [&] {
    return static_cast<Index>(u(rng) * static_cast<double>(cyl.size())) % static_cast<Index>(cyl.size());
  };
  for (int s = 0; s < 5; ++s)
    n.layout.linkers.push_back({randomPoint(randomCylinder()), randomPoint(randomCylinder()), 8.0, 35.0 * u(rng)});
  for (int s = 0; s < 3; ++s)
    n.layout.motors.push_back({randomPoint(randomCylinder()), randomPoint(randomCylinder()), 2.5, 200.0 * u(rng)});
  // Daughters: the first cylinders of filaments 1 and 2 on cylinders of filament 0.
  const Index daughter_first = static_cast<Index>(cylinders);
  const double cos70 = std::cos(70.0 * std::numbers::pi / 180.0);
  n.layout.branches.push_back(
      {randomPoint(1), cyl[daughter_first].bead0, cyl[daughter_first].bead1, 100.0, 100.0, cos70});
  n.layout.branches.push_back(
      {randomPoint(2), cyl[2 * daughter_first].bead0, cyl[2 * daughter_first].bead1, 50.0, 200.0, cos70});
  return n;
}

inline BoundaryConfig box(Vec3 lo, Vec3 hi) {
  BoundaryConfig b;
  b.min = lo;
  b.max = hi;
  return b;
}

inline BoundaryConfig sphere(Vec3 center, double radius) {
  BoundaryConfig b;
  b.shape = BoundaryConfig::Shape::kSphere;
  b.center = center;
  b.radius = radius;
  return b;
}

}  // namespace cortex::filtest
