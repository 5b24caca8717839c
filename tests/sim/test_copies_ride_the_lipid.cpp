// A whole run: copies that do not diffuse (D = 0) on a vesicle deflating from a sphere
// to v = 0.8, remeshed as it goes (1,556 -> ~4,900 vertices). Only the lipid moves them:
// the flow of each relaxation (mesh/lipid_flow.hpp) and every remeshing edit
// (mesh/copy_carrier.hpp). Spread by area at the start, they must still be spread by
// area at the end: chi-square per cell against a uniform density within 0.15 of 1
// (~7 standard deviations, sqrt(2/4900)). With the copies left in place by relaxations
// and remeshed by the former fixed rule the same run ended at 41.
#include <gtest/gtest.h>

#include <numeric>

#include "io/config.hpp"
#include "mesh/copy_statistics.hpp"
#include "sim/simulation.hpp"
#include "sim/system.hpp"

namespace cortex {
namespace {

TEST(CopiesRideTheLipid, ImmobileCopiesStaySpreadByAreaOnADeflatingRemeshedVesicle) {
  const Config config = parseConfig(R"([simulation]
end_time = 0.05
chemistry_window = 0.005
[[membrane]]
name = "vesicle"
shape = "sphere"
center = [1000.0, 1000.0, 1000.0]
radius = 600.0
mesh_size = 60.0
bending_modulus = 100.0
remesh = true
reduced_volume = [[0.0, 1.0], [0.05, 0.8]]
[[membrane.species]]
name = "U"
diffusion = 0.0
copies = 300000
[compartments]
size = 500.0
shape = [4, 4, 4]
)",
                                    "deflating.toml", ".", {});
  System system(config);
  RunObserver quiet;
  Simulation sim(system, config.simulation, config.mechanics, quiet);
  sim.run(true);
  const Membrane& m = *system.membranes()[0];
  const std::vector<int>& copies = m.speciesCopies()[0];
  EXPECT_EQ(std::accumulate(copies.begin(), copies.end(), 0L), 300000);
  EXPECT_GT(m.mesh().numVertices(), 3000) << "the remesher must have refined for the test to mean anything";
  const double chi2 = testing::chiSquarePerCell(m.mesh(), copies);
  std::printf("[ measured ] %d vertices, chi2/cell %.3f\n", static_cast<int>(m.mesh().numVertices()), chi2);
  EXPECT_NEAR(chi2, 1.0, 0.15);
}

}  // namespace
}  // namespace cortex
