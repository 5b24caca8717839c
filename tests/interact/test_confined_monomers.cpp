// Item 3 of issue 13: G-actin confined to a vesicle's inside while bundles growing inside
// deform it. Over the run, no monomer is made or lost (free copies + monomers in
// filaments stay the initial total), the vesicle does deform, and at the end every
// compartment holding free copies reaches inside the deformed membrane (its centre inside
// by the mesh's winding number, or a membrane vertex in it): the confinement followed
// the shape, not the initial sphere.
#include <gtest/gtest.h>

#include <cmath>

#include "interact/inside_membrane.hpp"
#include "io/config.hpp"
#include "sim/simulation.hpp"
#include "sim/system.hpp"

namespace cortex {
namespace {

// examples/vesicle_bundles.toml for 1 s: two antiparallel bundles in a 300 nm vesicle.
TEST(ConfinedMonomers, StayInsideTheVesicleTheBundlesDeform) {
  Config config = loadConfig(CORTEX_SOURCE_DIR "/examples/vesicle_bundles.toml", {"simulation.end_time=1.0"});
  System system(config);
  const auto monomers = [&] {
    long n = 0;
    for (const Filament& f : system.filaments()->filaments()) n += f.monomers();
    return n;
  };
  const auto free_copies = [&] {
    long n = 0;
    for (Index c = 0; c < system.grid().count(); ++c) n += system.chemistry()->copies(c, 0);
    return n;
  };
  const long total = monomers() + free_copies();
  RunObserver quiet;
  Simulation sim(system, config.simulation, config.mechanics, quiet);
  ASSERT_EQ(sim.run(true), RunOutcome::kFinished);
  EXPECT_EQ(monomers() + free_copies(), total);
  EXPECT_GT(monomers() * 2.7, 2 * 10 * 200.0);  // the bundles did grow, by more than their length

  const SurfaceMesh& mesh = system.membranes()[0]->mesh();
  double reach = 0.0;
  for (const Vec3& x : mesh.positions()) reach = std::max(reach, (x - Vec3(800, 400, 400)).norm());
  EXPECT_GT(reach, 330.0) << "the vesicle (radius 300 nm) was not deformed";
  const CompartmentGrid& grid = system.grid();
  int holding = 0;
  for (Index c = 0; c < grid.count(); ++c) {
    if (system.chemistry()->copies(c, 0) == 0) continue;
    ++holding;
    const Vec3 centre = grid.centre(c), half = Vec3::Constant(grid.size / 2);
    bool reaches = windingNumber(mesh, centre) > 0.5;
    for (const Vec3& x : mesh.positions())
      reaches = reaches || ((x - centre).cwiseAbs().array() <= half.array()).all();
    EXPECT_TRUE(reaches) << "free copies in compartment " << c << ", which lies wholly outside the vesicle";
  }
  EXPECT_GT(holding, 0);
}

// Nuclei form where the monomers are: with nucleation on, every filament, the nucleated
// ones included, lies inside the vesicle that confines G. Before, nuclei were placed
// anywhere in a compartment the vesicle cuts, and the compartments it barely cuts (high
// concentration in a small volume) formed the most: this run stopped at t = 0.09 s with
// a nucleus through the membrane, and seed 3 to 0.5 s grew two filaments wholly outside.
TEST(ConfinedMonomers, NucleiFormOnTheMonomersSide) {
  Config config = loadConfig(CORTEX_SOURCE_DIR "/examples/vesicle_bundles.toml",
                             {"simulation.end_time=0.3", "simulation.seed=3", "filament_type.0.nucleation_rate=0.0005"});
  System system(config);
  const std::size_t initial = system.filaments()->filaments().size();
  RunObserver quiet;
  Simulation sim(system, config.simulation, config.mechanics, quiet);
  ASSERT_EQ(sim.run(true), RunOutcome::kFinished);
  const auto& filaments = system.filaments()->filaments();
  EXPECT_GE(filaments.size(), initial + 10) << "too few nuclei to test where they form";
  const SurfaceMesh& mesh = system.membranes()[0]->mesh();
  for (std::size_t f = 0; f < filaments.size(); ++f)
    for (const Vec3& x : filaments[f].beads)
      EXPECT_GT(windingNumber(mesh, x), 0.5) << "filament " << f << " has a bead outside the vesicle";
}

// With G free on both sides of a vesicle, nuclei form on both sides but never straddle the
// membrane: one that would is a void event. Before, a dimer placed across the membrane
// stopped the run as a crossing (this run at t = 0.4 s, exit 1). Ends neither grow nor
// shrink here, so every filament is a nucleus as placed.
TEST(ConfinedMonomers, NucleiNeverStraddleAMembrane) {
  const Config config = parseConfig(R"([simulation]
seed = 1
end_time = 1.0
chemistry_window = 0.1
[[membrane]]
name = "ves"
shape = "sphere"
center = [1000.0, 1000.0, 1000.0]
radius = 900.0
mesh_size = 80.0
bending_modulus = 100.0
[compartments]
size = 250.0
shape = [8, 8, 8]
[[species]]
name = "G"
diffusion = 1.0e7
copies = 20000
[[filament_type]]
name = "actin"
monomer_species = "G"
plus_on = 0.0
minus_on = 0.0
plus_off = 0.0
minus_off = 0.0
nucleation_rate = 0.01
)",
                                    "straddle.toml", ".", {});
  System system(config);
  RunObserver quiet;
  Simulation sim(system, config.simulation, config.mechanics, quiet);
  ASSERT_EQ(sim.run(true), RunOutcome::kFinished);
  const SurfaceMesh& mesh = system.membranes()[0]->mesh();
  int inside = 0, outside = 0;
  for (const Filament& f : system.filaments()->filaments()) {
    const bool in = windingNumber(mesh, f.beads.front()) > 0.5;
    EXPECT_EQ(windingNumber(mesh, f.beads.back()) > 0.5, in) << "a nucleus across the membrane";
    ++(in ? inside : outside);
  }
  // Both sides nucleate, in proportion to their volumes (inside 3.05 of 8 µm³: 38%).
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

}  // namespace
}  // namespace cortex
