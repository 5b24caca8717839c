// placeFilaments: every bead inside the walls (with the margin), bundles on a hexagonal
// lattice of the given spacing, counts, determinism, isotropic random directions.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "filament/filament_placement.hpp"

namespace cortex {
namespace {

const Vec3 kBoxMin = Vec3::Zero(), kBoxMax = Vec3(1000, 1000, 1000);

FilamentConfig oneType() {
  FilamentConfig c;
  c.types.push_back(FilamentType{});
  return c;
}

FilamentInit randomFilaments(int count, double length) {
  FilamentInit f;
  f.type = "actin";
  f.count = count;
  f.length = length;
  return f;
}

// Every bead: the ends of every full cylinder and the plus end.
std::vector<Vec3> beads(const FilamentSeed& s, const FilamentType& t) {
  std::vector<Vec3> out;
  for (int m = 0; m < s.monomers; m += t.cylinder_monomers) out.push_back(s.minus_end + s.direction * m * t.monomer_size);
  out.push_back(s.minus_end + s.direction * s.monomers * t.monomer_size);
  return out;
}

std::vector<FilamentSeed> place(const FilamentConfig& c, std::uint64_t seed = 7) {
  RandomStream random(seed, StreamId::kInitialConditions);
  return placeFilaments(c, kBoxMin, kBoxMax, random);
}

TEST(FilamentPlacement, RandomFilamentsLieInsideTheBoxWithTheMargin) {
  FilamentConfig c = oneType();
  c.boundary = BoundaryConfig{};
  c.boundary->min = Vec3(100, 200, 300);
  c.boundary->max = Vec3(600, 500, 900);
  c.initial.push_back(randomFilaments(300, 250.0));
  const double margin = placementMargin(c);
  EXPECT_DOUBLE_EQ(margin, 2 * 2.7);
  const auto seeds = place(c);
  ASSERT_EQ(seeds.size(), 300u);
  for (const FilamentSeed& s : seeds) {
    EXPECT_EQ(s.monomers, std::lround(250.0 / 2.7));
    EXPECT_NEAR(s.direction.norm(), 1.0, 1e-12);
    for (const Vec3& b : beads(s, c.types[0])) {
      EXPECT_TRUE((b.array() >= (c.boundary->min.array() + margin)).all()) << b.transpose();
      EXPECT_TRUE((b.array() <= (c.boundary->max.array() - margin)).all()) << b.transpose();
    }
  }
}

TEST(FilamentPlacement, RandomFilamentsLieInsideTheSphere) {
  FilamentConfig c = oneType();
  c.boundary = BoundaryConfig{};
  c.boundary->shape = BoundaryConfig::Shape::kSphere;
  c.boundary->center = Vec3(400, 400, 400);
  c.boundary->radius = 200.0;
  c.initial.push_back(randomFilaments(300, 300.0));
  const auto seeds = place(c);
  ASSERT_EQ(seeds.size(), 300u);
  for (const FilamentSeed& s : seeds)
    for (const Vec3& b : beads(s, c.types[0]))
      EXPECT_LE((b - c.boundary->center).norm(), c.boundary->radius - placementMargin(c) + 1e-9);
}

TEST(FilamentPlacement, WithoutBoundaryTheGridBoxAndRegionsAreUsed) {
  FilamentConfig c = oneType();
  FilamentInit f = randomFilaments(100, 50.0);
  f.region = std::array<Vec3, 2>{Vec3(10, 20, 30), Vec3(40, 50, 60)};
  c.initial.push_back(f);
  c.initial.push_back(randomFilaments(100, 500.0));
  const auto seeds = place(c);
  ASSERT_EQ(seeds.size(), 200u);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    for (const Vec3& b : beads(seeds[i], c.types[0]))
      EXPECT_TRUE((b.array() >= kBoxMin.array()).all() && (b.array() <= kBoxMax.array()).all()) << b.transpose();
    if (i < 100) {
      EXPECT_TRUE((seeds[i].minus_end.array() >= f.region->at(0).array()).all());
      EXPECT_TRUE((seeds[i].minus_end.array() <= f.region->at(1).array()).all());
    }
  }
}

TEST(FilamentPlacement, CountsAndTypesFollowEachEntry) {
  FilamentConfig c = oneType();
  FilamentType mt;
  mt.name = "mt";
  mt.monomer_size = 8.0;
  c.types.push_back(mt);
  c.initial.push_back(randomFilaments(3, 2.0));  // rounds up to one monomer
  FilamentInit g = randomFilaments(0, 100.0);
  c.initial.push_back(g);
  g.count = 5;
  g.type = "mt";
  g.type_index = 1;
  c.initial.push_back(g);
  const auto seeds = place(c);
  ASSERT_EQ(seeds.size(), 8u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(seeds[i].type, 0);
    EXPECT_EQ(seeds[i].monomers, 1);
  }
  for (int i = 3; i < 8; ++i) {
    EXPECT_EQ(seeds[i].type, 1);
    EXPECT_EQ(seeds[i].monomers, 13);  // 100 / 8 = 12.5 rounds away from zero
  }
}

TEST(FilamentPlacement, SameSeedSameFilamentsOtherSeedOthers) {
  FilamentConfig c = oneType();
  c.initial.push_back(randomFilaments(50, 200.0));
  const auto a = place(c, 3), b = place(c, 3), other = place(c, 4);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].minus_end, b[i].minus_end);
    EXPECT_EQ(a[i].direction, b[i].direction);
  }
  EXPECT_NE(a[0].minus_end, other[0].minus_end);
}

TEST(FilamentPlacement, RandomDirectionsAreIsotropic) {
  FilamentConfig c = oneType();
  const int n = 2000;
  c.initial.push_back(randomFilaments(n, 20.0));
  const auto seeds = place(c);
  Vec3 mean = Vec3::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const FilamentSeed& s : seeds) {
    mean += s.direction / n;
    second += s.direction * s.direction.transpose() / n;
  }
  // Each component of a uniform unit vector has mean 0 and variance 1/3.
  const double sigma = std::sqrt(1.0 / 3.0 / n);
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(std::abs(mean[k]), 4 * sigma) << mean.transpose();
    // Var(x^2) = 1/5 - 1/9 = 4/45 for a uniform direction.
    EXPECT_NEAR(second(k, k), 1.0 / 3.0, 4 * std::sqrt(4.0 / 45.0 / n));
  }
}

TEST(FilamentPlacement, BundleIsAHexagonalLatticeOfParallelFilaments) {
  FilamentConfig c = oneType();
  c.boundary = BoundaryConfig{};
  c.boundary->min = Vec3::Zero();
  c.boundary->max = kBoxMax;
  FilamentInit f = randomFilaments(19, 300.0);  // the centre and two full rings
  f.placement = FilamentInit::Placement::kBundle;
  f.center = Vec3(500, 400, 600);
  f.direction = Vec3(1, 2, 2).normalized();
  f.spacing = 12.0;
  c.initial.push_back(f);
  const auto seeds = place(c);
  ASSERT_EQ(seeds.size(), 19u);
  const double length = seeds[0].monomers * 2.7;
  std::vector<Vec3> midpoints;
  for (const FilamentSeed& s : seeds) {
    EXPECT_NEAR((s.direction - f.direction).norm(), 0.0, 1e-12);
    midpoints.push_back(s.minus_end + s.direction * length / 2);
    EXPECT_NEAR((midpoints.back() - f.center).dot(f.direction), 0.0, 1e-9);  // centred along the axis
  }
  EXPECT_NEAR((midpoints[0] - f.center).norm(), 0.0, 1e-9);
  for (std::size_t i = 0; i < midpoints.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    int neighbours = 0;
    for (std::size_t j = 0; j < midpoints.size(); ++j) {
      if (i == j) continue;
      const double d = (midpoints[i] - midpoints[j]).norm();
      nearest = std::min(nearest, d);
      EXPECT_GT(d, f.spacing - 1e-9);
      neighbours += std::abs(d - f.spacing) < 1e-9;
    }
    EXPECT_NEAR(nearest, f.spacing, 1e-9);
    if (i <= 6) {
      EXPECT_EQ(neighbours, 6);  // the centre and the first ring are surrounded
    }
  }
}

// A mixed bundle has the same lattice, half its filaments reversed in place: ring
// neighbours antiparallel, every filament still centred, as many plus ends at each end
// as the count allows.
TEST(FilamentPlacement, MixedBundleAlternatesAroundEachRing) {
  FilamentConfig c = oneType();
  FilamentInit f = randomFilaments(19, 300.0);
  f.placement = FilamentInit::Placement::kBundle;
  f.center = Vec3(500, 400, 600);
  f.direction = Vec3(1, 2, 2).normalized();
  f.spacing = 12.0;
  FilamentConfig parallel = c;
  parallel.initial.push_back(f);
  f.mixed_polarity = true;
  c.initial.push_back(f);
  const auto seeds = place(c), reference = place(parallel);
  ASSERT_EQ(seeds.size(), 19u);
  const double length = seeds[0].monomers * 2.7;
  auto midpoint = [&](const FilamentSeed& s) -> Vec3 { return s.minus_end + s.direction * length / 2; };
  int forward = 0;
  for (std::size_t n = 0; n < seeds.size(); ++n) {
    const double sign = seeds[n].direction.dot(f.direction);
    EXPECT_NEAR(std::abs(sign), 1.0, 1e-12);
    forward += sign > 0;
    EXPECT_NEAR((midpoint(seeds[n]) - midpoint(reference[n])).norm(), 0.0, 1e-9);  // same lattice point
  }
  EXPECT_EQ(forward, 10);  // the centre, then 3 of 6 and 6 of 12 in the rings
  for (std::size_t n = 2; n < 7; ++n)  // first ring: consecutive lattice points are neighbours
    EXPECT_LT(seeds[n].direction.dot(seeds[n - 1].direction), 0.0);
}

TEST(FilamentPlacement, FilamentsThatDoNotFitAreInputErrors) {
  FilamentConfig c = oneType();
  c.boundary = BoundaryConfig{};
  c.boundary->max = Vec3(100, 100, 100);
  c.initial.push_back(randomFilaments(1, 10.0));
  c.initial.push_back(randomFilaments(1, 170.0));  // the diagonal is 173 nm, the margin takes more
  try {
    place(c);
    FAIL() << "placed a filament that cannot fit";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("filaments.1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("does not fit"), std::string::npos) << e.what();
  }
  FilamentConfig b = oneType();
  FilamentInit f = randomFilaments(7, 100.0);
  f.placement = FilamentInit::Placement::kBundle;
  f.center = Vec3(5, 500, 500);  // the first ring pokes out of the box
  f.direction = Vec3::UnitZ();
  b.initial.push_back(f);
  EXPECT_THROW(place(b), InputError);
}

}  // namespace
}  // namespace cortex
