// The issue's stress test: 100 anchored filaments at random orientations growing into a
// patch (8 s) and 100 into a closed vesicle remeshed as it deforms (3 s), with fast
// exchange at the ends (on 116/(µM·s) at 50 µM, off 1000/s, so ends stall against the
// membrane and keep polymerizing and depolymerizing there), relaxed every 0.1 s: at least
// 10⁶ polymerization events in all (about 0.8 M and 0.3 M), ~90 s on one core, and no filament ever passes through a membrane (the run
// checks every cylinder against the triangles near it before and after each relaxation,
// and stops with an error at the first crossing). Without the ratchet seeing the
// membrane between relaxations, ends polymerize through it within the first simulated
// second (docs/coupling.md).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "io/config.hpp"
#include "sim/simulation.hpp"
#include "sim/system.hpp"

namespace cortex {
namespace {

// Walls at the grid's faces: filaments growing sideways past the patch's edge would leave
// the grid, which stops a run (their ends would react with the edge compartment).
const char* kCommon = R"(
[compartments]
size = 250.0
shape = [2, 2, 2]

[boundary]

[[species]]
name = "G"
diffusion = 2.0e7
concentration = 50.0

[[filament_type]]
name = "actin"
monomer_species = "G"
cylinder_monomers = 10
plus_on = 116.0
plus_off = 1000.0
minus_on = 0.0
minus_off = 0.0
)";

// A 2-cylinder filament (54 nm) whose plus end lies at `tip`, growing along `direction`.
std::string filament(const Vec3& tip, const Vec3& direction) {
  const Vec3 centre = tip - 27.0 * direction;
  return "[[filaments]]\nlength = 54.0\nplacement = \"bundle\"\nfixed_minus_end = true\n" +
         std::string("center = [") + std::to_string(centre.x()) + ", " + std::to_string(centre.y()) + ", " +
         std::to_string(centre.z()) + "]\ndirection = [" + std::to_string(direction.x()) + ", " +
         std::to_string(direction.y()) + ", " + std::to_string(direction.z()) + "]\n";
}

// Plus ends 3-20 nm short of the membrane, pointing at it within 72° (patch) or 60°
// (vesicle, from inside) of its normal.
std::string patchConfig(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::string toml = std::string(kCommon) + R"(
[simulation]
end_time = 8.0
chemistry_window = 0.1
snapshot_interval = 8.0

[[membrane]]
name = "patch"
shape = "plane"
center = [250.0, 250.0, 300.0]
size = [480.0, 480.0]
mesh_size = 30.0
boundary = "fixed"
bending_modulus = 100.0
tension = 1.0
area_model = "none"
)";
  for (int i = 0; i < 100; ++i) {
    const double cos_t = 0.3 + 0.7 * u(rng), phi = 2 * M_PI * u(rng), sin_t = std::sqrt(1 - cos_t * cos_t);
    const Vec3 direction(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
    toml += filament(Vec3(100 + 300 * u(rng), 100 + 300 * u(rng), 300 - 3 - 17 * u(rng)), direction);
  }
  return toml;
}

std::string vesicleConfig(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::string toml = std::string(kCommon) + R"(
[simulation]
end_time = 3.0
chemistry_window = 0.1
snapshot_interval = 3.0

[[membrane]]
name = "vesicle"
shape = "sphere"
center = [250.0, 250.0, 250.0]
radius = 180.0
mesh_size = 30.0
bending_modulus = 100.0
remesh = true
)";
  const Vec3 centre(250, 250, 250);
  for (int i = 0; i < 100; ++i) {
    const Vec3 radial = Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    const Vec3 across = radial.cross(Vec3(gauss(rng), gauss(rng), gauss(rng))).normalized();
    const double cos_t = 0.5 + 0.5 * u(rng);
    const Vec3 direction = cos_t * radial + std::sqrt(1 - cos_t * cos_t) * across;
    toml += filament(centre + (180.0 - 8.0 - 3 - 17 * u(rng)) * radial, direction);
  }
  return toml;
}

std::int64_t polymerizations(const System& system) {
  std::int64_t n = 0;
  const auto& reactions = system.chemistryModel().reactions;
  for (std::size_t i = 0; i < reactions.size(); ++i)
    if (reactions[i].equation.find("plus-end growth") != std::string::npos) n += system.chemistry()->reactionEvents()[i];
  return n;
}

TEST(MembraneCrossingStress, AMillionPolymerizationsIntoAPatchAndAVesicleWithoutACrossing) {
  std::mt19937 rng(2026);
  std::int64_t total = 0;
  for (const std::string& toml : {patchConfig(rng), vesicleConfig(rng)}) {
    const Config config = parseConfig(toml, "stress.toml", ".", {});
    System system(config);
    RunObserver quiet;
    Simulation sim(system, config.simulation, config.mechanics, quiet);
    ASSERT_NO_THROW(sim.run(true));  // a crossing would be a RunError naming it
    const std::int64_t n = polymerizations(system);
    EXPECT_GT(n, 250000) << system.membranes()[0]->name();
    EXPECT_GT(system.filamentChemistry()->maxEndLoad(), 0.5);  // ends do push on the membrane
    total += n;
  }
  EXPECT_GE(total, 1000000);
  RecordProperty("polymerizations", std::to_string(total));
}

}  // namespace
}  // namespace cortex
