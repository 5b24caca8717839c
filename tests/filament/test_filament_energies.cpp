// The filament energy terms against closed-form values, and the exclusion neighbour list
// against an O(N^2) reference (their gradients: tests/test_energy_gradients.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <numbers>
#include <random>

#include "filament/boundary_energy.hpp"
#include "filament/branch_energy.hpp"
#include "filament/excluded_volume_energy.hpp"
#include "filament/filament_bending_energy.hpp"
#include "filament/spring_energy.hpp"
#include "filament/stretching_energy.hpp"
#include "filament_networks.hpp"

namespace cortex {
namespace {

using namespace filtest;

// A layout of explicitly placed beads, offset by kOffset.
struct Beads {
  FilamentLayout layout;
  std::vector<double> x;
  explicit Beads(std::initializer_list<Vec3> beads) {
    layout.bead_offset = kOffset;
    layout.num_beads = static_cast<Index>(beads.size());
    layout.version = 1;
    x.assign(3 * kOffset, 0.0);
    for (const Vec3& b : beads) x.insert(x.end(), {b.x(), b.y(), b.z()});
  }
  Vec3 gradient(const std::vector<double>& g, Index b) const {
    return Eigen::Map<const Vec3>(g.data() + 3 * (kOffset + b));
  }
  double evaluate(EnergyTerm& term, std::vector<double>* g = nullptr) {
    if (g) g->assign(x.size(), 0.0);
    return term.evaluate({x.data(), g ? g->data() : nullptr, ++layout.version});
  }
};

TEST(FilamentStretching, KnownStretch) {
  const std::vector<FilamentType> types = testTypes();
  Beads n{Vec3(1, 2, 3), Vec3(1, 2, 15)};
  n.layout.cylinders.push_back({0, 1, 0, 0, 10.0});
  FilamentStretchingEnergy term(n.layout, types);
  std::vector<double> g;
  EXPECT_NEAR(n.evaluate(term, &g), 0.5 * 100.0 * 4.0, 1e-12);
  EXPECT_NEAR((n.gradient(g, 1) - Vec3(0, 0, 200.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((n.gradient(g, 0) + n.gradient(g, 1)).norm(), 0.0, 1e-12);
}

TEST(FilamentBending, KnownAngle) {
  const std::vector<FilamentType> types = testTypes();
  const double theta = 0.7;
  Beads n{Vec3(0, 0, 0), Vec3(20, 0, 0), Vec3(20 + 15 * std::cos(theta), 15 * std::sin(theta), 0)};
  n.layout.hinges.push_back({0, 1, 2, 0});
  FilamentBendingEnergy term(n.layout, types);
  std::vector<double> g;
  EXPECT_NEAR(n.evaluate(term, &g), 672.0 * (1.0 - std::cos(theta)), 1e-10);
  // Bending is translation invariant: the three bead gradients cancel.
  EXPECT_NEAR((n.gradient(g, 0) + n.gradient(g, 1) + n.gradient(g, 2)).norm(), 0.0, 1e-10);
}

// Two cylinders of type 0 (k = 10 pN/nm, d0 = 9 nm).
Beads twoCylinders(Vec3 a0, Vec3 a1, Vec3 b0, Vec3 b1) {
  Beads n{a0, a1, b0, b1};
  n.layout.cylinders.push_back({0, 1, 0, 0, 20.0});
  n.layout.cylinders.push_back({2, 3, 1, 0, 20.0});
  return n;
}

TEST(CylinderExclusion, PerpendicularCrossing) {
  const std::vector<FilamentType> types = testTypes();
  Beads n = twoCylinders(Vec3(-10, 0, 0), Vec3(10, 0, 0), Vec3(0, -10, 3), Vec3(0, 10, 3));
  CylinderExclusionEnergy term(n.layout, types);
  std::vector<double> g;
  EXPECT_NEAR(n.evaluate(term, &g), 0.5 * 10.0 * 36.0, 1e-10);
  // Each bead of A carries half of dE/dz = +k (d0 - d) = 60 (A is below B).
  EXPECT_NEAR((n.gradient(g, 0) - Vec3(0, 0, 30)).norm(), 0.0, 1e-10);
  EXPECT_NEAR((n.gradient(g, 3) - Vec3(0, 0, -30)).norm(), 0.0, 1e-10);
}

TEST(CylinderExclusion, ParallelOverlappingSegments) {
  const std::vector<FilamentType> types = testTypes();
  Beads n = twoCylinders(Vec3(0, 0, 0), Vec3(20, 0, 0), Vec3(10, 4, 0), Vec3(30, 4, 0));
  CylinderExclusionEnergy term(n.layout, types);
  std::vector<double> g;
  EXPECT_NEAR(n.evaluate(term, &g), 0.5 * 10.0 * 25.0, 1e-10);
  // Whichever closest pair is chosen, the total push on A is k (d0 - d) along -y.
  EXPECT_NEAR((n.gradient(g, 0) + n.gradient(g, 1) - Vec3(0, 50, 0)).norm(), 0.0, 1e-10);
  EXPECT_NEAR((n.gradient(g, 2) + n.gradient(g, 3) + Vec3(0, 50, 0)).norm(), 0.0, 1e-10);
}

TEST(CylinderExclusion, ZeroBeyondCutoff) {
  const std::vector<FilamentType> types = testTypes();
  Beads n = twoCylinders(Vec3(-10, 0, 0), Vec3(10, 0, 0), Vec3(0, -10, 9.01), Vec3(0, 10, 9.01));
  CylinderExclusionEnergy term(n.layout, types);
  std::vector<double> g;
  EXPECT_EQ(n.evaluate(term, &g), 0.0);
  for (double v : g) EXPECT_EQ(v, 0.0);
}

TEST(CylinderExclusion, CoincidentSegmentsStayFinite) {
  const std::vector<FilamentType> types = testTypes();
  for (Beads n : {twoCylinders(Vec3(-10, 0, 0), Vec3(10, 0, 0), Vec3(0, -10, 0), Vec3(0, 10, 0)),
                  twoCylinders(Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(5, 0, 0), Vec3(15, 0, 0))}) {
    CylinderExclusionEnergy term(n.layout, types);
    std::vector<double> g;
    EXPECT_NEAR(n.evaluate(term, &g), 0.5 * 10.0 * 81.0, 1e-10);
    double norm2 = 0.0;
    for (double v : g) {
      EXPECT_TRUE(std::isfinite(v));
      norm2 += v * v;
    }
    EXPECT_GT(norm2, 0.0) << "touching segments must still be pushed apart";
  }
}

TEST(CylinderExclusion, BranchJointPairIsExempt) {
  const std::vector<FilamentType> types = testTypes();
  // The daughter (beads 2, 3) starts on the mother (beads 0, 1): d = 0.
  Beads n = twoCylinders(Vec3(0, 0, 0), Vec3(20, 0, 0), Vec3(10, 0, 0), Vec3(15, 10, 0));
  CylinderExclusionEnergy unbranched(n.layout, types);
  EXPECT_NEAR(n.evaluate(unbranched), 0.5 * 10.0 * 81.0, 1e-10);
  n.layout.branches.push_back({{0, 1, 0.5}, 2, 3, 100.0, 100.0, 0.5});
  CylinderExclusionEnergy branched(n.layout, types);
  EXPECT_EQ(n.evaluate(branched), 0.0);
}

// E over all pairs, no neighbour list.
double bruteForceExclusion(const FilamentLayout& l, const std::vector<FilamentType>& types, const double* x) {
  auto bead = [&](Index b) { return Vec3(Eigen::Map<const Vec3>(x + 3 * (l.bead_offset + b))); };
  double e = 0.0;
  for (std::size_t i = 0; i < l.cylinders.size(); ++i)
    for (std::size_t j = i + 1; j < l.cylinders.size(); ++j) {
      const Cylinder &a = l.cylinders[i], &b = l.cylinders[j];
      if (a.bead0 == b.bead0 || a.bead0 == b.bead1 || a.bead1 == b.bead0 || a.bead1 == b.bead1) continue;
      const double d0 = 0.5 * (types[a.type].excluded_volume_distance + types[b.type].excluded_volume_distance);
      const double k = 0.5 * (types[a.type].excluded_volume_stiffness + types[b.type].excluded_volume_stiffness);
      const double d = closestPoints(bead(a.bead0), bead(a.bead1), bead(b.bead0), bead(b.bead1)).delta.norm();
      if (d < d0) e += 0.5 * k * (d0 - d) * (d0 - d);
    }
  return e;
}

TEST(CylinderExclusion, NeighbourListMatchesBruteForce) {
  const std::vector<FilamentType> types = testTypes();
  Network n = randomNetwork(11, 100, 3, 250.0);  // 300 cylinders
  n.layout.branches.clear();                     // the reference knows nothing of branches
  CylinderExclusionEnergy term(n.layout, types, 10.0);
  std::mt19937 rng(5);
  std::uint64_t version = 100;
  auto moveAll = [&](double amplitude) {
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    for (std::size_t i = 3 * kOffset; i < n.x.size(); ++i) n.x[i] += u(rng);
  };
  auto check = [&] {
    const double reference = bruteForceExclusion(n.layout, types, n.x.data());
    EXPECT_GT(reference, 0.0);
    EXPECT_NEAR(term.evaluate({n.x.data(), nullptr, ++version}), reference, 1e-10 * reference);
  };
  check();
  EXPECT_EQ(term.rebuilds(), 1);
  // Small moves (|displacement| < skin/2 per bead in total) keep the list.
  moveAll(1.0);
  check();
  moveAll(1.0);
  check();
  EXPECT_EQ(term.rebuilds(), 1);
  for (int round = 0; round < 5; ++round) {
    moveAll(25.0);
    check();
  }
  EXPECT_EQ(term.rebuilds(), 6);
  // A new layout version forces a rebuild even without motion.
  ++n.layout.version;
  check();
  EXPECT_EQ(term.rebuilds(), 7);
}

TEST(FilamentBoundary, BoxForceAtKnownDistance) {
  const BoundaryConfig b = box(Vec3(0, 0, 0), Vec3(1000, 1000, 500));
  const double d = 4.0;
  const Vec3 f = boundaryForce(b, Vec3(d, 500, 250));
  EXPECT_NEAR(f.x(), 41.0 * std::exp(-d / 2.7), 1e-12);
  EXPECT_NEAR(f.y(), 0.0, 1e-12);
  const Vec3 f_top = boundaryForce(b, Vec3(500, 500, 500 - d));
  EXPECT_NEAR(f_top.z(), -41.0 * std::exp(-d / 2.7), 1e-12);
}

TEST(FilamentBoundary, SphereForceAtKnownDistance) {
  const BoundaryConfig b = sphere(Vec3(10, 20, 30), 100.0);
  const Vec3 direction = Vec3(1, -2, 2).normalized();
  const double d = 5.0;
  const Vec3 f = boundaryForce(b, b.center + (100.0 - d) * direction);
  EXPECT_NEAR((f + 41.0 * std::exp(-d / 2.7) * direction).norm(), 0.0, 1e-12);
  EXPECT_NEAR(boundaryEnergy(b, b.center + (100.0 - d) * direction), 41.0 * 2.7 * std::exp(-d / 2.7), 1e-12);
}

TEST(FilamentBoundary, ForceIsMinusGradient) {
  for (const BoundaryConfig& b : {box(Vec3(0, 0, 0), Vec3(50, 60, 70)), sphere(Vec3(1, 2, 3), 40.0)}) {
    Beads n{Vec3(3, 57, 20), Vec3(25, 1.5, 68)};
    BoundaryRepulsionEnergy term(n.layout, b);
    std::vector<double> g;
    const double e = n.evaluate(term, &g);
    EXPECT_NEAR(e, boundaryEnergy(b, beadOf({n.layout, n.x}, 0)) + boundaryEnergy(b, beadOf({n.layout, n.x}, 1)),
                1e-12);
    for (Index i = 0; i < 2; ++i)
      EXPECT_NEAR((boundaryForce(b, beadOf({n.layout, n.x}, i)) + n.gradient(g, i)).norm(), 0.0, 1e-12);
  }
}

TEST(FilamentSpring, TensionSign) {
  Beads n{Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 30, 0), Vec3(10, 30, 0)};
  const Spring stretched{{0, 1, 0.5}, {2, 3, 0.5}, 8.0, 25.0};
  const Spring compressed{{0, 1, 0.5}, {2, 3, 0.5}, 8.0, 40.0};
  EXPECT_NEAR(springTension(stretched, n.x.data(), kOffset), 8.0 * 5.0, 1e-12);
  EXPECT_NEAR(springTension(compressed, n.x.data(), kOffset), -8.0 * 10.0, 1e-12);
  n.layout.linkers = {stretched};
  SpringEnergy term(n.layout, n.layout.linkers, "linkers");
  EXPECT_EQ(term.name(), "linkers");
  std::vector<double> g;
  EXPECT_NEAR(n.evaluate(term, &g), 0.5 * 8.0 * 25.0, 1e-12);
  // Stretched: the gradient pulls point a's beads towards b (dE/dy < 0 there).
  EXPECT_NEAR(n.gradient(g, 0).y(), -20.0, 1e-12);
}

TEST(FilamentBranch, MinimumAtRestAngle) {
  const double theta0 = 70.0 * std::numbers::pi / 180.0;
  auto joint = [&](double theta) {
    const Vec3 site(6, 0, 0);
    Beads n{Vec3(0, 0, 0), Vec3(20, 0, 0), site, site + 15.0 * Vec3(std::cos(theta), std::sin(theta), 0)};
    n.layout.branches.push_back({{0, 1, 0.3}, 2, 3, 100.0, 100.0, std::cos(theta0)});
    return n;
  };
  Beads at_rest = joint(theta0);
  BranchEnergy rest_term(at_rest.layout);
  EXPECT_EQ(rest_term.name(), "branching");
  std::vector<double> g;
  EXPECT_NEAR(at_rest.evaluate(rest_term, &g), 0.0, 1e-20);
  for (double v : g) EXPECT_NEAR(v, 0.0, 1e-10);
  for (double dtheta : {-0.1, 0.1}) {
    Beads n = joint(theta0 + dtheta);
    BranchEnergy term(n.layout);
    const double dc = std::cos(theta0 + dtheta) - std::cos(theta0);
    EXPECT_NEAR(n.evaluate(term), 100.0 * dc * dc, 1e-10);
  }
}

}  // namespace
}  // namespace cortex
