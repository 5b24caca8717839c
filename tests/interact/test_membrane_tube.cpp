// A bundle polymerizing into a patch under tension pulls out a tube (thesis section 2.3):
// its radius tends to R₀ = √(κ/2γ) and the force holding it to f₀ = 2π√(2κγ) (Derényi,
// Jülicher and Prost 2002), both for E = κ/2 ∫(2H)² dA + γA. Checked at two tensions (R₀ =
// 50 and 32 nm), each on a tube about ten radii long, within 10% (the tolerance;
// measured 2–4%).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/config.hpp"
#include "sim/simulation.hpp"
#include "sim/system.hpp"
#include "tube_pulling.hpp"

namespace cortex {
namespace {

// Four rigid filaments under a 1 µm patch (bench/tube_pulling.hpp), fast ends (10×
// actin's rates) at 6 µM: stall force 7.3 pN per filament, 29 pN for the bundle, above
// the peak force (≈ 1.15 f₀) the tube has to pass.
std::string tubeConfig(double tension, double end_time) {
  bench::TubePulling s;
  s.tension = tension;
  s.end_time = end_time;
  return bench::tubePullingConfig(s);
}

TEST(MembraneTube, ABundlePullsATubeOfRadiusSqrtKappaOver2GammaAtForce2PiSqrt2KappaGamma) {
  const double kappa = 100.0;
  struct Case {
    double tension, end_time;
  };
  for (const Case& c : {Case{0.02, 4.0}, Case{0.05, 5.0}}) {
    const Config config = parseConfig(tubeConfig(c.tension, c.end_time), "tube.toml", ".", {});
    System system(config);
    RunObserver quiet;
    Simulation sim(system, config.simulation, config.mechanics, quiet);
    ASSERT_EQ(sim.run(true), RunOutcome::kFinished);
    const double r0 = std::sqrt(kappa / (2 * c.tension)), f0 = 2 * M_PI * std::sqrt(2 * kappa * c.tension);

    // The tube's radius: mean distance of the vertices in a 20 nm slab at 60% of its
    // height (between the neck and the cap) from the bundle's axis.
    const FilamentNetwork& net = *system.filaments();
    Eigen::Vector2d axis = Eigen::Vector2d::Zero();
    for (const Filament& f : net.filaments()) axis += f.beads.back().head<2>() / 4.0;
    const auto& vertices = system.membranes()[0]->mesh().positions();
    double top = -1e9;
    for (const Vec3& v : vertices) top = std::max(top, v.z());
    const double height = top - 200.0, slab = 200.0 + 0.6 * height;
    double radius = 0.0;
    int n = 0;
    for (const Vec3& v : vertices)
      if (std::abs(v.z() - slab) < 10.0) radius += (v.head<2>() - axis).norm(), ++n;
    radius /= n;
    // The force holding it: the membrane's push on every bead, along the tube.
    const Eigen::VectorXd contact = system.forceField().contactForces(system.coordinates());
    double force = 0.0;
    for (Index b = 0; b < net.numPoints(); ++b) force -= contact[3 * (net.offset() + b) + 2];
    std::printf("[ measured ] γ = %.2f pN/nm: tube %.0f nm long (%.1f R₀), radius %.1f nm (R₀ %.1f, %+.1f%%), "
                "force %.2f pN (f₀ %.2f, %+.1f%%)\n",
                c.tension, height, height / r0, radius, r0, 100 * (radius / r0 - 1), force, f0, 100 * (force / f0 - 1));
    EXPECT_GT(height, 10 * r0);  // a tube, not a tent
    EXPECT_GT(n, 50);
    EXPECT_NEAR(radius, r0, 0.10 * r0);
    EXPECT_NEAR(force, f0, 0.10 * f0);
  }
}

}  // namespace
}  // namespace cortex
