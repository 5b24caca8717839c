// Membranes and filaments in one System: an anchored filament pressed into a patch under
// tension comes to rest with the membrane's push on its tip equal to its own compression
// (force balance between the two bodies, relaxed in turn); the interaction is on by
// default and off on request; a filament through a membrane at the start is an input
// error and the crossing check finds a cylinder through a triangle.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "filament/filament.hpp"
#include "interact/membrane_crossing.hpp"
#include "interact/triangle_queries.hpp"
#include "membrane/shape_relaxation.hpp"
#include "mesh/planar_patch.hpp"
#include "sim/simulation.hpp"
#include "sim/system.hpp"
#include "test_configs.hpp"

namespace cortex {
namespace {

struct ResultRecorder final : public RunObserver {
  MinimizationResult last;
  void onWindow(const System&, const MinimizationResult& r) override { last = r; }
};

// A 400 nm patch at z = 250 nm, in the middle of the default 500 nm box (tension 0.02 pN/nm, κ = 100 pN·nm, fixed edge) and one
// anchored filament along z whose tip starts `gap` nm below it.
Config pushConfig(double gap) {
  MembraneMechanics mechanics;
  mechanics.bending.modulus = Schedule(100.0);
  mechanics.tension.tension = Schedule(0.02);
  const SurfaceMesh patch = SurfaceMesh::fromSoup(planarPatch(Vec3(250, 250, 250), 400.0, 400.0, 20.0), "patch");
  Config c = testing::configWith({testing::membraneOf("patch", patch, mechanics)});
  FilamentConfig filaments;
  filaments.types.resize(1);
  // A soft filament (actin's is 100 pN/nm): it shortens by nanometres under the push, so
  // the membrane has to follow it back, and one pass of each relaxation would not do.
  filaments.types[0].stretching_stiffness = 0.5;
  FilamentInit init;
  init.length = 108.0;
  init.placement = FilamentInit::Placement::kBundle;
  init.direction = Vec3::UnitZ();
  init.center = Vec3(253.0, 248.0, 250.0 - 54.0 - gap);
  init.fixed_minus_end = true;
  filaments.initial.push_back(init);
  c.filaments = filaments;
  c.membrane_filament = MembraneBeadExclusionParams{};
  return c;
}

// The tip starts 2 nm under the membrane, where the repulsion is ~2πk/h³ = 80 pN: the
// membrane gives way and the filament shortens until the push on the tip equals the
// filament's compression k (l0 − l). Both are relaxed to force_tolerance (0.1 pN), so
// they agree within twice that. The same with either filament minimizer.
TEST(MembraneFilamentSystem, APushedPatchAndTheFilamentComeToRestTogether) {
  for (const bool preconditioned : {false, true}) {
    SCOPED_TRACE(preconditioned ? "preconditioned L-BFGS" : "conjugate gradients");
    Config config = pushConfig(2.0);
    config.mechanics.precondition_filaments = preconditioned;
    System system(config);
    ResultRecorder recorder;
    Simulation sim(system, config.simulation, config.mechanics, recorder);
    ASSERT_EQ(sim.run(true), RunOutcome::kFinished);
    EXPECT_TRUE(recorder.last.converged) << recorder.last.stop_reason;
    const FilamentNetwork& net = *system.filaments();
    const Filament& f = net.filaments()[0];
    ASSERT_EQ(f.beads.size(), 2u);
    const Eigen::VectorXd contact = system.forceField().contactForces(system.coordinates());
    const Vec3 push = contact.segment<3>(3 * (net.offset() + 1));
    const double length = (f.beads[1] - f.beads[0]).norm();
    const double compression = net.type(0).stretching_stiffness * (f.monomers() * net.type(0).monomer_size - length);
    EXPECT_LT(push.z(), -0.5);  // pushed back (0.76 pN here: the soft filament yields)
    EXPECT_NEAR(-push.z(), compression, 0.2);
    // The membrane moved up over the tip, which stays below it.
    double top = -1e9;
    for (const Vec3& v : system.membranes()[0]->mesh().positions()) top = std::max(top, v.z());
    EXPECT_GT(top, 251.0);
    EXPECT_LT(f.beads[1].z(), top);
    EXPECT_FALSE(findMembraneCrossing(*system.membranes()[0], net));
    // And the membrane is at rest under the filament as it ended: relaxing it again
    // finds nothing to do (relaxing each body only once would leave it pushed).
    const ShapeRelaxationReport again =
        relaxMembraneShape(*system.membranes()[0], system.forceField(), system.time(), ShapeRelaxationSettings{});
    EXPECT_EQ(again.iterations, 0);
    EXPECT_TRUE(again.converged);
    // The membrane's energy breakdown names the interaction.
    bool listed = false;
    for (const TermEnergy& e : system.forceField().breakdown(system.coordinates()))
      listed = listed || (e.owner == "patch" && e.name == "filament_exclusion" && e.energy > 0);
    EXPECT_TRUE(listed);
  }
}

// The filaments relax on their own coordinates (ForceField::Alone, the network moved to
// offset zero) beside a membrane that stays where it is held: the energy and forces must
// be the network's part of those of the whole vector, frozen minus end included. Equal
// to round-off (1e-12 relative): the same terms sum the same pairs.
TEST(MembraneFilamentSystem, TheFilamentsAloneSeeTheirPartOfTheWholeForces) {
  System system(pushConfig(2.0));
  FilamentNetwork& net = *system.filaments();
  ASSERT_GT(net.offset(), 0);  // after the membrane's vertices: the offset matters
  ForceField& field = system.forceField();
  const std::vector<EnergyTerm*> terms = field.termsOf(net.name());
  Eigen::VectorXd whole = system.coordinates();
  whole.segment<3>(3 * (net.offset() + 1)) += Vec3(0.3, -0.2, 0.5);  // off its rest
  Eigen::VectorXd whole_gradient;
  const double whole_energy = field.evaluateTerms(terms, whole, &whole_gradient);
  const Eigen::Index first = 3 * net.offset(), count = 3 * net.numPoints();
  Eigen::VectorXd x = whole.segment(first, count), gradient;
  double energy = 0.0;
  {
    const BodyAtOffsetZero at_zero(net);
    ForceField::Alone alone(field, terms, net, first);
    energy = alone.valueAndGradient(x, gradient);
  }
  EXPECT_EQ(net.offset(), first / 3);  // put back
  ASSERT_EQ(gradient.size(), count);
  EXPECT_GT(whole_energy, 0.0);
  EXPECT_NEAR(energy, whole_energy, 1e-12 * std::abs(whole_energy));
  const Eigen::VectorXd expected = whole_gradient.segment(first, count);
  EXPECT_GT(expected.norm(), 1.0);  // the push of the membrane and the stretch
  EXPECT_LE((gradient - expected).norm(), 1e-12 * expected.norm());
  EXPECT_EQ(gradient.head<3>().norm(), 0.0);  // the anchored minus end
}

TEST(MembraneFilamentSystem, AClampedAnchorHoldsTheDirectionAPinnedOneLetsItTurn) {
  // A two-cylinder filament tilted 20° from the normal, its tip 2 nm under the patch: the
  // membrane's push has a sideways part. Pinned, the filament turns about its minus end;
  // clamped, its first cylinder keeps its direction exactly. The flag survives a restart.
  for (bool clamped : {false, true}) {
    Config config = pushConfig(2.0);
    FilamentInit& init = config.filaments->initial[0];
    init.length = 216.0;  // 80 monomers: two cylinders
    init.direction = Vec3(std::sin(0.35), 0.0, std::cos(0.35));
    init.center = Vec3(253.0, 248.0, 250.0 - 2.0) - 108.0 * init.direction;
    init.clamped_minus_end = clamped;
    System system(config);
    const Vec3 before = system.filaments()->filaments()[0].beads[1] - system.filaments()->filaments()[0].beads[0];
    ResultRecorder recorder;
    Simulation sim(system, config.simulation, config.mechanics, recorder);
    ASSERT_EQ(sim.run(true), RunOutcome::kFinished);
    const auto& beads = system.filaments()->filaments()[0].beads;
    const double turned = std::acos(std::min(1.0, (beads[1] - beads[0]).normalized().dot(before.normalized())));
    if (clamped) {
      EXPECT_EQ(turned, 0.0);
      const System restarted(config, &static_cast<const SystemState&>(system.state()));
      EXPECT_TRUE(restarted.filaments()->filaments()[0].minus_clamped);
    } else {
      EXPECT_GT(turned, 0.01) << "radians";
    }
  }
}

TEST(MembraneFilamentSystem, AFilamentThroughTheMembraneAtTheStartIsAnInputError) {
  const Config config = pushConfig(-30.0);  // the tip 30 nm above the patch
  try {
    System system(config);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("passes through membrane \"patch\""), std::string::npos) << e.what();
  }
  Config off = config;
  off.membrane_filament.reset();  // without the interaction, nothing keeps them apart
  EXPECT_NO_THROW(System{off});
}

TEST(MembraneFilamentSystem, TheCrossingCheckFindsEveryCylinderThroughATriangle) {
  // Random segments against a rough patch: the check agrees with testing every cylinder
  // against every triangle.
  const Config config = pushConfig(5.0);
  System system(config);
  const Membrane& m = *system.membranes()[0];
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int found = 0;
  for (int k = 0; k < 300; ++k) {
    FilamentConfig fc;
    fc.types.resize(1);
    FilamentNetwork net(fc);
    const Vec3 start(250 + 150 * u(rng), 250 + 150 * u(rng), 250 + 60 * u(rng));
    net.addFilament(makeStraightFilament(0, start, Vec3(u(rng), u(rng), u(rng)).normalized(), 60, 15, 2.7));
    bool brute = false;
    const auto& beads = net.filaments()[0].beads;
    for (std::size_t i = 0; i + 1 < beads.size() && !brute; ++i)
      for (const Tri& t : m.topology().triangles)
        brute = brute || segmentMeetsTriangle(beads[i], beads[i + 1], m.mesh().positions()[t[0]],
                                              m.mesh().positions()[t[1]], m.mesh().positions()[t[2]]);
    EXPECT_EQ(findMembraneCrossing(m, net).has_value(), brute) << "case " << k;
    found += brute;
  }
  EXPECT_GT(found, 50);
  EXPECT_LT(found, 250);
}

}  // namespace
}  // namespace cortex
