// Filaments placed at random inside a closed membrane (`[[filaments]] inside`, for the
// thesis' fig. 2.4a): the winding number tells inside from outside on a rough, non-convex
// mesh; placed filaments lie wholly inside, clear of the membrane by the interaction's
// cut-off; bad uses are input errors naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "interact/inside_membrane.hpp"
#include "interact/membrane_crossing.hpp"
#include "io/config.hpp"
#include "sim/system.hpp"
#include "test_meshes.hpp"

namespace cortex {
namespace {

TEST(InsideMembrane, TheWindingNumberIsOneInsideAndZeroOutside) {
  // A rough sphere (vertices moved up to 15% of the radius): points are classified by
  // their distance from the centre wherever that is unambiguous (below 0.8 R or above
  // 1.2 R); the winding number is an integer to 1e-9 everywhere off the surface.
  const SurfaceMesh mesh = testing::sphereMesh(100.0, 3, 15.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-150.0, 150.0);
  int inside = 0, outside = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const double w = windingNumber(mesh, p);
    EXPECT_NEAR(w, std::round(w), 1e-9);
    if (p.norm() < 80.0) {
      EXPECT_NEAR(w, 1.0, 1e-9);
      ++inside;
    }
    if (p.norm() > 120.0) {
      EXPECT_NEAR(w, 0.0, 1e-9);
      ++outside;
    }
  }
  EXPECT_GT(inside, 100);  // 8% of the cube: ~160
  EXPECT_GT(outside, 200);
}

TEST(InsideMembrane, ASegmentIsInsideOnlyWhenEveryPointIsClearOfTheMembrane) {
  const SurfaceMesh mesh = testing::sphereMesh(100.0, 4);  // vertices on R = 100, faces ≥ 99.2
  EXPECT_TRUE(segmentInside(mesh, Vec3(-70, 0, 0), Vec3(70, 0, 0), 20.0));
  EXPECT_FALSE(segmentInside(mesh, Vec3(-85, 0, 0), Vec3(70, 0, 0), 20.0));  // an end 15 nm from it
  EXPECT_FALSE(segmentInside(mesh, Vec3(-50, 90, 0), Vec3(50, 90, 0), 5.0));  // a chord: the middle pokes out
  EXPECT_FALSE(segmentInside(mesh, Vec3(0, 0, 130), Vec3(0, 0, 200), 5.0));   // outside
}

std::string vesicleWithFilaments(const std::string& filaments) {
  return R"(
[simulation]
end_time = 0.0

[compartments]
size = 250.0
shape = [4, 4, 4]

[[species]]
name = "G"
diffusion = 2.0e7
concentration = 1.0

[[membrane]]
name = "cell"
shape = "ellipsoid"
center = [500.0, 500.0, 500.0]
radii = [400.0, 300.0, 250.0]
mesh_size = 40.0

[[membrane]]
name = "sheet"
shape = "plane"
center = [500.0, 500.0, 900.0]
size = [600.0, 600.0]
mesh_size = 50.0

[[filament_type]]
name = "actin"
monomer_species = "G"
)" + filaments;
}

TEST(InsideMembrane, RandomFilamentsInsideAVesicleStayInsideClearOfIt) {
  const Config config = parseConfig(vesicleWithFilaments(R"(
[[filaments]]
count = 60
length = 270.0
inside = "cell"
)"),
                                    "inside.toml", ".", {});
  const System system(config);
  const Membrane& cell = *system.membranes()[0];
  const FilamentNetwork& net = *system.filaments();
  ASSERT_EQ(net.filaments().size(), 60u);
  double lowest_x = 1e9, highest_x = -1e9;
  for (const Filament& f : net.filaments())
    for (const Vec3& b : f.beads) {
      EXPECT_GT(windingNumber(cell.mesh(), b), 0.5);
      EXPECT_GE(distanceToMesh(cell.mesh(), b), 20.0 - 1e-9);  // the default cut-off
      lowest_x = std::min(lowest_x, b.x()), highest_x = std::max(highest_x, b.x());
    }
  EXPECT_FALSE(findMembraneCrossing(cell, net));
  // Spread over the ellipsoid's long axis (±400 nm), not bunched at the centre.
  EXPECT_LT(lowest_x, 250.0);
  EXPECT_GT(highest_x, 750.0);
}

TEST(InsideMembrane, BadUsesAreInputErrorsNamingTheKey) {
  const auto refusal = [](const std::string& filaments) {
    try {
      const Config config = parseConfig(vesicleWithFilaments(filaments), "inside.toml", ".", {});
      System system(config);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(refusal("[[filaments]]\ninside = \"nucleus\"\n").find("filaments.0.inside: no membrane is named \"nucleus\""),
            std::string::npos);
  EXPECT_NE(refusal("[[filaments]]\ninside = \"sheet\"\n").find("\"sheet\" is open"), std::string::npos);
  EXPECT_NE(refusal("[[filaments]]\nplacement = \"bundle\"\ninside = \"cell\"\n").find("inside"), std::string::npos);
  // Longer than the vesicle is wide: a named refusal, not a hang.
  EXPECT_NE(refusal("[[filaments]]\nlength = 1200.0\ninside = \"cell\"\n").find("does not fit inside membrane \"cell\""),
            std::string::npos);
}

}  // namespace
}  // namespace cortex
