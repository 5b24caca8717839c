// Where a membrane species' copies start (issue 14): uniformly by dual-cell area over the
// vertices its region holds, none outside, and with a footprint none above what a cell's
// area holds (the engine's crowding cap). The placement draws a multinomial over the
// vertices, so its work does not grow with the number of copies.
//
// - Uniform by area: Pearson chi-square per cell against counts ∝ |C_j|, expected
//   1 ± sqrt(2/cells) = 1 ± 0.04 for the ~1,340 cells of the half sphere; the bound 1.2 is
//   5 standard deviations. With 2e9 copies (the documented maximum) too, which the
//   one-copy-at-a-time placement took 100 s to place.
// - With a footprint at 95% of the places: every cell within its room, the total exact.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "io/config.hpp"
#include "mesh/copy_carrier.hpp"
#include "sim/system.hpp"
#include "mesh/copy_statistics.hpp"

namespace cortex {
namespace {

std::string halfSphereConfig(long copies, const std::string& footprint) {
  return fmt::format(R"([[membrane]]
name = "vesicle"
shape = "sphere"
center = [500.0, 500.0, 500.0]
radius = 400.0
mesh_size = 30.0
bending_modulus = 100.0
[[membrane.species]]
name = "M"
diffusion = 1.0e4
copies = {}
region = {{ min = [0.0, 0.0, 500.0], max = [1000.0, 1000.0, 1000.0] }}
{}
[compartments]
size = 1000.0
shape = [1, 1, 1]
)",
                     copies, footprint);
}

const auto upperHalf = [](const Vec3& x) { return x.z() >= 500.0; };

void expectUniformByArea(long copies) {
  const Config config = parseConfig(halfSphereConfig(copies, ""), "placement.toml", ".", {});
  System system(config);
  const Membrane& m = *system.membranes()[0];
  const std::vector<int>& n = m.speciesCopies()[0];
  long total = 0, outside = 0;
  for (Index v = 0; v < m.mesh().numVertices(); ++v) {
    total += n[v];
    if (!upperHalf(m.mesh().positions()[v])) outside += n[v];
  }
  EXPECT_EQ(total, copies);
  EXPECT_EQ(outside, 0);
  EXPECT_LT(testing::chiSquarePerCell(m.mesh(), n, upperHalf), 1.2) << copies << " copies";
}

TEST(SurfacePlacement, CopiesStartUniformByAreaInTheirRegion) {
  expectUniformByArea(30000);
  expectUniformByArea(2000000000);
}

TEST(SurfacePlacement, AFootprintCapsEveryCellAndTheTotalStaysExact) {
  // Count the places first: a cell of area A holds floor(A / a) copies of footprint a.
  const double footprint = 150.0;  // nm², about a fifth of a mean cell at 30 nm edges
  const Config probe = parseConfig(halfSphereConfig(1, ""), "placement.toml", ".", {});
  System empty(probe);
  const SurfaceMesh& mesh = empty.membranes()[0]->mesh();
  const std::vector<double> area = dualCellAreas(mesh);
  long places = 0;
  for (Index v = 0; v < mesh.numVertices(); ++v)
    if (upperHalf(mesh.positions()[v])) places += static_cast<long>(std::floor(area[v] / footprint));
  const long copies = static_cast<long>(0.95 * static_cast<double>(places));
  const Config config =
      parseConfig(halfSphereConfig(copies, fmt::format("footprint = {}", footprint)), "placement.toml", ".", {});
  System system(config);
  const std::vector<int>& n = system.membranes()[0]->speciesCopies()[0];
  long total = 0, over = 0;
  for (Index v = 0; v < mesh.numVertices(); ++v) {
    total += n[v];
    over += n[v] * footprint > area[v] * (1.0 + 1e-12);
  }
  EXPECT_EQ(total, copies);
  EXPECT_EQ(over, 0) << "cells above their crowding cap";
}

}  // namespace
}  // namespace cortex
