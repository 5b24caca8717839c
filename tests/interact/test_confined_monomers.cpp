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

}  // namespace
}  // namespace cortex
