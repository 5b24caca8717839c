// Curvature generation against linear theory (issue 14; thesis 3.2.5): a stripe of
// immobile coat proteins across a flat patch under tension γ with fixed edges. The coat
// sets κ(φ) and the spontaneous curvature H_c φ (membrane/protein_coat.hpp), so for small
// slopes the height h(x) across the stripe obeys, with u = κ(∇²h − 2c) − γh harmonic and
// decaying (u = 0),
//   h'' − λ_in² h = 2c  (|x| < a, c = H_c φ, λ_in² = γ/κ(φ)),   h'' − λ² h = 0 outside,
// h and h' continuous at |x| = a (κ(h'' − 2c) = γh is then continuous too), so
//   h(x) = 2c/λ_in² [A cosh(λ_in x) − 1] inside,  A = 1/(cosh λ_in a + (λ_in/λ) sinh λ_in a),
//   h(x) = h(a) e^{−λ(|x| − a)} outside,
// up to the sign of the normal (cortex: a positive H_p bulges along the patch's normal).
// a and φ are measured on the mesh (the coated vertices' dual cells, the copies' area).
// Two cases differing in every parameter and in the sign of H_p; the heights across the
// stripe's middle at x − x₀ = 0, ±a/2, ±a, ±2a within 5% of h(0): the theory is linear
// (slopes ≤ 0.1, errors ~1%), the stripe's edge is resolved by 15 nm cells (a/15 = 4–7),
// and the fixed y edges are 5.6/λ away or more. Without the coat's generation (H_c → H_p,
// i.e. the κ_p/(κ_l + κ_p) forgotten) h(0) doubles. A third, weak coat (the first case at
// φ = 0.15 and H_p = 0.01 /nm, a 6 nm bulge) drives forces below the membrane's own force scale everywhere:
// the default relaxation stopped it at 2.0 nm until it also required a small predicted
// step (shape_relaxation.cpp, kStepTolerance).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "io/config.hpp"
#include "membrane/shape_relaxation.hpp"
#include "sim/simulation.hpp"
#include "sim/surface_graph.hpp"
#include "sim/system.hpp"

namespace cortex {
namespace {

struct StripeCase {
  double tension;          // pN/nm
  double kappa_protein;    // pN nm
  double protein_curvature;  // 1/nm
  double half_width;       // nm, of the start region
  double coverage = 0.5;   // φ of the coat (copies of 2 nm²)
};

std::string stripeConfig(const StripeCase& c) {
  return fmt::format(R"([simulation]
end_time = 0.001
chemistry_window = 0.001
[[membrane]]
name = "patch"
shape = "plane"
center = [500.0, 400.0, 0.0]
size = [1000.0, 800.0]
mesh_size = 15.0
boundary = "fixed"
bending_modulus = 100.0
tension = {}
area_model = "none"
[[membrane.species]]
name = "C"
density = {}
region = {{ min = [{}, -1.0, -1.0], max = [{}, 801.0, 1.0] }}
[membrane.species.curvature]
area = 2.0
bending_modulus = {}
spontaneous_curvature = {}
generates = true
[compartments]
size = 1100.0
shape = [1, 1, 1]
)",
                     c.tension, c.coverage * 5e5, 500.0 - c.half_width, 500.0 + c.half_width, c.kappa_protein,
                     c.protein_curvature);
}

class CurvatureGeneration : public ::testing::TestWithParam<StripeCase> {};

TEST_P(CurvatureGeneration, CoatedStripeOnATensedPatchBulgesAsLinearTheorySays) {
  const StripeCase c = GetParam();
  const Config config = parseConfig(stripeConfig(c), "stripe.toml", ".", {});
  System system(config);
  RunObserver quiet;
  Simulation sim(system, config.simulation, config.mechanics, quiet);
  ASSERT_EQ(sim.run(true), RunOutcome::kFinished);

  const Membrane& m = *system.membranes()[0];
  const auto& x = m.mesh().positions();
  const std::vector<int>& copies = m.speciesCopies()[0];
  const std::vector<double> cell = dualCellAreas(m.mesh());
  double coated = 0.0;
  long total = 0;
  for (Index v = 0; v < m.mesh().numVertices(); ++v)
    if (copies[v] > 0) coated += cell[v], total += copies[v];
  const double a = coated / 800.0 / 2.0, phi = 2.0 * static_cast<double>(total) / coated;
  ASSERT_NEAR(phi, c.coverage, 0.01);

  const double kl = 100.0, kp = c.kappa_protein;
  const double kin = 1.0 / ((1.0 - phi) / kl + phi / (kl + kp));
  const double curvature = c.protein_curvature * kp / (kl + kp) * phi;
  const double li = std::sqrt(c.tension / kin), lo = std::sqrt(c.tension / kl);
  const double scale = 2.0 * curvature / (li * li);
  const double amp = 1.0 / (std::cosh(li * a) + li / lo * std::sinh(li * a));
  const auto theory = [&](double u) {
    u = std::abs(u);
    if (u < a) return -scale * (amp * std::cosh(li * u) - 1.0);
    return -scale * (amp * std::cosh(li * a) - 1.0) * std::exp(-lo * (u - a));
  };
  // The mean height of the vertices near (500 + u, 400).
  const auto height = [&](double u) {
    double sum = 0.0;
    int n = 0;
    for (Index v = 0; v < m.mesh().numVertices(); ++v)
      if (std::abs(x[v][0] - 500.0 - u) < 8.0 && std::abs(x[v][1] - 400.0) < 60.0) sum += x[v][2], ++n;
    return sum / n;
  };
  const double h0 = theory(0.0);
  EXPECT_GT(std::abs(h0), 5.0) << "too small a bulge to test";
  for (double u : {0.0, -0.5 * a, 0.5 * a, -a, a, -2.0 * a, 2.0 * a})
    EXPECT_NEAR(height(u), theory(u), 0.05 * std::abs(h0)) << "x − x₀ = " << u << " nm; a = " << a << " nm";
}

// A 300 nm vesicle (volume free, area held) with a coat of the given density (copies per
// µm², 2 nm² each: φ = density / 500,000) in the box region, H_p (default 0.03 /nm), κ_p = κ_l.
std::string coatedVesicleConfig(double density, const std::string& region, double protein_curvature = 0.03,
                                double mesh_size = 20.0) {
  return fmt::format(R"([simulation]
end_time = 0.01
chemistry_window = 0.005
[[membrane]]
name = "vesicle"
shape = "sphere"
center = [400.0, 400.0, 400.0]
radius = 300.0
mesh_size = {}
bending_modulus = 100.0
remesh = true
[[membrane.species]]
name = "C"
density = {}
region = {}
[membrane.species.curvature]
area = 2.0
bending_modulus = 100.0
spontaneous_curvature = {}
generates = true
[compartments]
size = 400.0
shape = [2, 2, 2]
)",
                     mesh_size, density, region, protein_curvature);
}

constexpr const char* kUpperCap = "{ min = [0.0, 0.0, 634.0], max = [800.0, 800.0, 800.0] }";

// A coat's copies are counted per vertex, so sliding a vertex within the surface dilutes
// or concentrates its cell's coat: the coat pushes in-plane, and the normal components of
// those pushes add up to a net force and torque that the relaxation's rigid-body rows hold
// (docs/membrane.md). The shape is at rest once the normal forces are balanced with those
// reactions: the reported residual is that quantity, within the tolerance the relaxation
// converged to (it read 1.3-2.0× the tolerance on the upper cap, 4-7× on the side cap,
// while the rows' reactions were counted as residual), and relaxing again finds the shape
// at rest: one iteration at most, for a residual that ended just under the tolerance,
// releasing less than 10⁻³ k_BT (measured: 6·10⁻⁵ k_BT, 1.1·10⁻⁷ of the energy). Two coats
// that differ in place, extent and density, and the same vesicle without one: the rows'
// net force comes from the coat (0.32 and 2.6 pN against 0.004 pN without; asserted > 10×).
TEST(CurvatureGeneration, ACoatedVesicleRelaxesToRestWithTheRigidRowsReactionsReported) {
  const auto relaxTwice = [](double density, const std::string& region) {
    SCOPED_TRACE(fmt::format("density {} in {}", density, region));
    const Config config = parseConfig(coatedVesicleConfig(density, region), "coat.toml", ".", {});
    System system(config);
    Membrane& m = *system.membranes()[0];
    const ShapeRelaxationReport first = relaxMembraneShape(m, system.forceField(), 0.0, ShapeRelaxationSettings{});
    system.layOut();
    EXPECT_TRUE(first.converged) << first.stop_reason;
    EXPECT_LE(first.max_normal_force, first.force_tolerance);
    const ShapeRelaxationReport again = relaxMembraneShape(m, system.forceField(), 0.0, ShapeRelaxationSettings{});
    EXPECT_TRUE(again.converged) << again.stop_reason;
    EXPECT_LE(again.iterations, 1);
    EXPECT_NEAR(again.energy, first.energy, 1e-3 * constants::kBoltzmann * constants::kDefaultTemperature);
    EXPECT_LE(again.max_normal_force, again.force_tolerance);
    return first.held_force;
  };
  const double bare = relaxTwice(1.0, kUpperCap);  // ~0 copies: φ ~ 2e-6
  EXPECT_GT(relaxTwice(100000.0, kUpperCap), 10.0 * bare);
  EXPECT_GT(relaxTwice(150000.0, "{ min = [560.0, 0.0, 0.0], max = [800.0, 800.0, 800.0] }"), 10.0 * bare);
}

// The model's limit, as an error: a coat whose cells the relaxation stretches is thinned
// by the mesh, not by physics, as far as the lipid's flow does not bring its copies back
// together. A small dense cap (φ = 0.5 above 95% of the height of a 300 nm vesicle with
// its volume free, H_p = 0.06 /nm: H_c φ = 0.015 /nm) domes out at once; its mean
// coverage fell 0.51 → 0.20 in the first relaxation with the copies left in place, 0.33
// riding the flow by upwind sub-steps, and falls to 0.39 with the flow passing the lipid
// on in order (docs/proteins.md). The run must stop with the reason (exit 1), not report
// that shape. (The larger cap above 78% at H_p = 0.03 /nm that this test used before now
// keeps 0.46 and runs.)
const std::string kSmallCap = "{ min = [0.0, 0.0, 685.0], max = [800.0, 800.0, 800.0] }";

TEST(CurvatureGenerationLimit, ACoatThinnedByStretchingEndsTheRun) {
  const Config config = parseConfig(coatedVesicleConfig(250000.0, kSmallCap, 0.06), "cap.toml", ".", {});
  System system(config);
  RunObserver quiet;
  Simulation sim(system, config.simulation, config.mechanics, quiet);
  try {
    sim.run(true);
    FAIL() << "the run should have stopped";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("thinned the coat"), std::string::npos) << e.what();
  }
}

// The thinning is the mesh's: the coat's edge is smeared over a cell's width, so it falls
// with the edge length, about linearly (the same cap's first relaxation: 23%, 18%, 12%,
// 10%, 7% at 20, 16, 12, 10, 8 nm; docs/proteins.md). At 8 nm the cap stays within the
// limit and domes the vesicle (reduced volume 0.92, from 1): the run finishes. Bounds:
// under the 10% limit, and the reduced volume below 0.95, far from the sphere's 1 and
// from the 0.92 measured.
TEST(CurvatureGenerationLimit, AFinerMeshKeepsTheSameCapWithinTheLimit) {
  Config config = parseConfig(coatedVesicleConfig(250000.0, kSmallCap, 0.06, 8.0), "cap.toml", ".", {});
  config.simulation.end_time = 0.0;  // the first relaxation is the one that thins
  System system(config);
  const Membrane& m = *system.membranes()[0];
  const double before = m.coatCoverage();
  RunObserver quiet;
  Simulation sim(system, config.simulation, config.mechanics, quiet);
  ASSERT_EQ(sim.run(true), RunOutcome::kFinished);
  EXPECT_GT(m.coatCoverage(), 0.9 * before);
  const MeshGeometry g = m.currentGeometry();
  EXPECT_LT(g.volume / sphereVolumeOfArea(g.area), 0.95) << "the cap did not dome the vesicle";
}

INSTANTIATE_TEST_SUITE_P(TwoStripes, CurvatureGeneration,
                         ::testing::Values(StripeCase{0.02, 100.0, 0.005, 100.0}, StripeCase{0.05, 300.0, -0.004, 60.0},
                                           StripeCase{0.02, 100.0, 0.01, 100.0, 0.15}),
                         [](const auto& info) {
                           return std::string(info.index == 0 ? "wide" : info.index == 1 ? "narrow" : "weak");
                         });

}  // namespace
}  // namespace cortex
