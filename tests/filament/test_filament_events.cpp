// The individual filament events and force laws: what each reaction does to the network,
// the conservation laws it keeps, and the loads that feed back into rates.
#include <gtest/gtest.h>

#include <cmath>

#include "../chem/chem_statistics.hpp"
#include "core/error.hpp"
#include "filament_fixtures.hpp"
#include "sim/filament_builder.hpp"

namespace cortex {
namespace {

using filtest::Rig;

FilamentType inertActin() {
  FilamentType t = filtest::actin();
  t.plus_on = t.plus_off = t.minus_on = t.minus_off = 0.0;
  return t;
}

// Actin that neither grows nor shrinks, and a myosin (species 1) that only walks.
FilamentConfig walkingMotorOnInertActin(double walk_rate) {
  FilamentConfig config;
  config.types = {inertActin()};
  MotorType m;
  m.name = "myo";
  m.species = "M";
  m.species_index = 1;
  m.walk_rate = walk_rate;
  m.on_rate = m.off_rate = 0.0;
  config.motors = {m};
  return config;
}

TEST(FilamentForceLaws, SlipCatchAndHillFollowTheirFormulas) {
  FilamentNetwork net({});
  FilamentChemistry chem(net, CompartmentGrid{}, {}, filtest::kT);
  LinkerType l;
  l.slip_length = 0.24;
  EXPECT_NEAR(chem.slipFactor(l, 10.0), std::exp(10.0 * 0.24 / filtest::kT), 1e-12);
  EXPECT_NEAR(chem.slipFactor(l, -10.0), chem.slipFactor(l, 10.0), 1e-12);  // any load speeds unbinding
  MotorType m;
  EXPECT_NEAR(FilamentChemistry::catchFactor(m, 12.62), std::exp(-1.0), 1e-12);
  EXPECT_EQ(FilamentChemistry::catchFactor(m, -5.0), 1.0);
  EXPECT_EQ(FilamentChemistry::walkFactor(m, 0.0), 1.0);
  EXPECT_NEAR(FilamentChemistry::walkFactor(m, 45.0), (90.0 - 45.0) / (90.0 + 45.0 / 0.2), 1e-12);
  EXPECT_EQ(FilamentChemistry::walkFactor(m, 90.0), 0.0);
  EXPECT_EQ(FilamentChemistry::walkFactor(m, 200.0), 0.0);
}

// Motors with heads (parallel cluster model): unloaded ensemble lifetime
// ((1 + k_h/k_off)^N - 1)/(N k_h), load shared by N_b(F) = rho N + beta F/N heads,
// walking (N - N_b)/N_b per bound head; the rates are off_rate and walk_rate times these
// factors.
TEST(FilamentForceLaws, MotorHeadsSetUnbindingAndWalking) {
  MotorType m;  // k_h = 0.2/s, k_off = 1.7/s per head, beta = 2/pN
  const int n = 20;
  const double rho = 0.2 / 1.9;
  const double lifetime = (std::pow(1.0 + 0.2 / 1.7, n) - 1.0) / (n * 0.2);
  EXPECT_NEAR(FilamentChemistry::catchFactor(m, 0.0, n) * m.off_rate, 1.0 / lifetime, 1e-12);
  EXPECT_NEAR(FilamentChemistry::catchFactor(m, -3.0, n), FilamentChemistry::catchFactor(m, 0.0, n), 1e-15);
  EXPECT_NEAR(1.0 / (FilamentChemistry::catchFactor(m, 0.0, 15) * m.off_rate), 1.4345, 1e-4);  // s, 15 heads
  EXPECT_NEAR(1.0 / (FilamentChemistry::catchFactor(m, 0.0, 30) * m.off_rate), 4.5213, 1e-4);  // s, 30 heads
  const double f = 20.0, nb = rho * n + 2.0 * f / n;
  EXPECT_NEAR(FilamentChemistry::boundHeads(m, f, n), nb, 1e-12);
  EXPECT_NEAR(FilamentChemistry::catchFactor(m, f, n), FilamentChemistry::catchFactor(m, 0.0, n) * std::exp(-f / (nb * 12.62)),
              1e-12);
  EXPECT_NEAR(FilamentChemistry::walkFactor(m, 0.0, n), (1.0 - rho) / rho, 1e-12);  // 8.5 for NMIIA
  EXPECT_NEAR(FilamentChemistry::walkFactor(m, f, n), (n - nb) / nb * (90.0 - f) / (90.0 + f / 0.2), 1e-12);
  EXPECT_EQ(FilamentChemistry::walkFactor(m, 95.0, n), 0.0);
  // Without heads nothing changes.
  EXPECT_EQ(FilamentChemistry::catchFactor(m, 12.62, 0), FilamentChemistry::catchFactor(m, 12.62));
  EXPECT_EQ(FilamentChemistry::walkFactor(m, 45.0, 0), FilamentChemistry::walkFactor(m, 45.0));
  // k_h → 0: each head's binding is the only way a bound head is replaced, so the
  // unloaded ensemble unbinds as one head does (factor → 1, exactly computed below
  // round-off, where (1 + x)^N − 1 gave 0/0), and the walking factor (N − N_b)/N_b, which
  // grows as 1/k_h, stops at the 10⁶ cap (it was infinite: an internal error).
  for (const double kh : {1e-6, 1e-12, 1e-300}) {
    m.head_binding_rate = kh;
    EXPECT_NEAR(FilamentChemistry::catchFactor(m, 0.0, n), 1.0, 1e-4) << kh;  // 1 − (N−1)x/2 + …, x = k_h/k_off
    EXPECT_LE(FilamentChemistry::walkFactor(m, 0.0, n), 1e6) << kh;
  }
  m.head_binding_rate = 1e-300;
  EXPECT_EQ(FilamentChemistry::walkFactor(m, 0.0, n), 1e6);
}

// A filament growing straight at another one's side feels the excluded-volume push on its
// plus end: load k (d0 - d), ratchet factor exp(-load delta / kT).
TEST(FilamentRatchetLoad, IncludesExcludedVolumeFromOtherFilaments) {
  FilamentConfig config;
  config.types = {filtest::actin()};
  const double gap = 4.0;  // nm between the tip and the obstacle's axis, d0 = 7 nm
  Rig rig(2000.0, {1, 1, 1}, {{"G", 0.0}}, {1000}, config, [&](FilamentNetwork& net) {
    net.addFilament(makeStraightFilament(0, Vec3(500.0, 1000.0, 1000.0), Vec3::UnitX(), 40, 40, 2.7));
    net.addFilament(
        makeStraightFilament(0, Vec3(608.0 + gap, 900.0, 1000.0), Vec3::UnitY(), 80, 40, 2.7));
  });
  const FilamentType& t = config.types[0];
  const double load = t.excluded_volume_stiffness * (t.excluded_volume_distance - gap);
  EXPECT_NEAR(rig.chemistry->endLoad(0, true), load, 1e-9);
  EXPECT_NEAR(rig.chemistry->ratchetFactor(0, true), std::exp(-load * 2.7 / filtest::kT), 1e-12);
  EXPECT_EQ(rig.chemistry->endLoad(0, false), 0.0);
}

// A wall standing still between relaxations (as a membrane does) in front of a growing
// plus end: force F0 e^(−(x_wall − x)/λ) against the growth direction.
struct ExponentialWall final : public EndLoadProbe {
  double x_wall, f0 = 10.0, lambda = 2.7;
  Vec3 forceAt(Index /*filament*/, const Vec3& p, bool plus_end) const override {
    return plus_end ? Vec3(-f0 * std::exp(-(x_wall - p.x()) / lambda), 0.0, 0.0) : Vec3::Zero();
  }
};

// Growth steps within one chemistry window: each moves the end closer to the wall, and
// the ratchet sees it at once (the last relaxation's load with the wall's part replaced
// by the wall's push where the end now is), not at the next relaxation.
TEST(FilamentRatchetLoad, AGrowingEndFeelsAStillBodyBeforeTheNextRelaxation) {
  FilamentConfig config;
  config.types = {filtest::actin()};
  config.types[0].plus_off = config.types[0].minus_on = config.types[0].minus_off = 0.0;
  Rig rig(2000.0, {1, 1, 1}, {{"G", 0.0}}, {100000}, config, [&](FilamentNetwork& net) {
    net.addFilament(makeStraightFilament(0, Vec3(500.0, 1000.0, 1000.0), Vec3::UnitX(), 40, 40, 2.7));
  });
  ExponentialWall wall;
  const double tip0 = rig.network->filaments()[0].beads.back().x();
  wall.x_wall = tip0 + 12.0;
  rig.chemistry->setEndLoadProbe(&wall);
  rig.relaxed();  // the last relaxation: no contact term here, so its load is 0
  EXPECT_EQ(rig.chemistry->endLoad(0, true), 0.0);
  for (int step = 0; step < 40 && rig.network->filaments()[0].beads.back().x() < tip0 + 5.0; ++step)
    rig.engine->advance(rig.engine->time() + 0.001);
  const double tip = rig.network->filaments()[0].beads.back().x();
  ASSERT_GE(tip, tip0 + 5.0);  // grown at least two monomers within the window
  const double load = wall.f0 * (std::exp(-(wall.x_wall - tip) / wall.lambda) - std::exp(-12.0 / wall.lambda));
  EXPECT_NEAR(rig.chemistry->endLoad(0, true), load, 1e-12 * load);
  EXPECT_NEAR(rig.chemistry->ratchetFactor(0, true), std::exp(-load * 2.7 / filtest::kT), 1e-12);
  EXPECT_LT(rig.chemistry->ratchetFactor(0, true), 0.6);
  // The next relaxation starts over from the forces it finds.
  rig.relaxed();
  EXPECT_EQ(rig.chemistry->endLoad(0, true), 0.0);
}

// One motor on two fixed antiparallel filaments, no load: each end steps towards its
// filament's plus end at walk_rate until it reaches the end.
TEST(FilamentMotor, WalksTowardsPlusEndsAtItsRate) {
  const FilamentConfig config = walkingMotorOnInertActin(2.0);
  const MotorType& m = config.motors[0];
  const int monomers = 2000;  // 5.4 µm: room for ~1000 steps of 2 monomers
  const int runs = 40;
  const double T = 20.0;
  std::vector<double> steps;
  for (int run = 0; run < runs; ++run) {
    Rig rig(6000.0, {1, 1, 1}, {{"G", 0.0}, {"M", 0.0}}, {0, 0}, config, [&](FilamentNetwork& net) {
      net.addFilament(makeStraightFilament(0, Vec3(200.0, 3000.0, 3000.0), Vec3::UnitX(), monomers, 40, 2.7));
      net.addFilament(makeStraightFilament(0, Vec3(5600.0, 3200.0, 3000.0), -Vec3::UnitX(), monomers, 40, 2.7));
      Binding b;
      b.filament = {0, 1};
      b.site = {10, 10};
      // Unstretched at binding; tensions are only recomputed after minimizations (none here).
      b.rest_length = (net.sitePosition(BinderKind::kMotor, 0, 1, 10) - net.sitePosition(BinderKind::kMotor, 0, 0, 10)).norm();
      net.bind(BinderKind::kMotor, b);
    }, 100 + run);
    rig.engine->advance(T);
    const Binding& b = rig.network->motors().front();
    steps.push_back(static_cast<double>(b.site[0] - 10));
    steps.push_back(static_cast<double>(b.site[1] - 10));
  }
  const auto mo = chemtest::moments(steps);
  std::printf("[ measured ] motor steps per end in %g s: %.2f +- %.2f, expected %.1f\n", T, mo.mean,
              mo.standardError, m.walk_rate * T);
  EXPECT_NEAR(mo.mean, m.walk_rate * T, 4.0 * mo.standardError);
  EXPECT_NEAR(mo.variance, m.walk_rate * T, 0.35 * m.walk_rate * T);  // Poisson steps
}

// With heads, an unloaded motor end walks at walk_rate (1 - rho)/rho, whatever its head
// count (100 heads here: the ensemble then practically never detaches, 3e-4 /s), and the
// network counts the steps.
TEST(FilamentMotor, WithHeadsWalksAtTheEnsembleRate) {
  FilamentConfig config = walkingMotorOnInertActin(0.2);
  MotorType& m = config.motors[0];
  m.off_rate = 1.7;  // one head's; the duty ratio is 0.2/1.9
  m.heads_min = m.heads_max = 100;
  const double rate = m.walk_rate * m.off_rate / m.head_binding_rate;  // 1.7 /s per end
  const double T = 10.0;
  std::vector<double> steps;
  for (int run = 0; run < 20; ++run) {
    Rig rig(6000.0, {1, 1, 1}, {{"G", 0.0}, {"M", 0.0}}, {0, 0}, config, [&](FilamentNetwork& net) {
      net.addFilament(makeStraightFilament(0, Vec3(200.0, 3000.0, 3000.0), Vec3::UnitX(), 2000, 40, 2.7));
      net.addFilament(makeStraightFilament(0, Vec3(5600.0, 3200.0, 3000.0), -Vec3::UnitX(), 2000, 40, 2.7));
      Binding b;
      b.filament = {0, 1};
      b.site = {10, 10};
      b.heads = 100;
      b.rest_length = (net.sitePosition(BinderKind::kMotor, 0, 1, 10) - net.sitePosition(BinderKind::kMotor, 0, 0, 10)).norm();
      net.bind(BinderKind::kMotor, b);
    }, 300 + run);
    rig.engine->advance(T);
    const Binding& b = rig.network->motors().front();
    steps.push_back(static_cast<double>(b.site[0] + b.site[1] - 20));
    EXPECT_EQ(rig.network->events().motor_steps, b.site[0] + b.site[1] - 20);
  }
  const auto mo = chemtest::moments(steps);
  std::printf("[ measured ] steps per motor with heads in %g s: %.1f +- %.1f, expected %.1f\n", T, mo.mean,
              mo.standardError, 2 * rate * T);
  EXPECT_NEAR(mo.mean, 2 * rate * T, 4.0 * mo.standardError);
}

// A motor between two fixed antiparallel filaments walks its ends apart, stretching
// itself, until the Hill law stops it at the stall force: tensions are recomputed every
// 0.05 s as in a run, and the last step may overshoot by one step's worth of tension.
TEST(FilamentMotor, StallsAtTheStallForce) {
  const FilamentConfig config = walkingMotorOnInertActin(5.0);
  const MotorType& m = config.motors[0];
  Rig rig(4000.0, {1, 1, 1}, {{"G", 0.0}, {"M", 0.0}}, {0, 0}, config, [&](FilamentNetwork& net) {
    net.addFilament(makeStraightFilament(0, Vec3(500.0, 1900.0, 2000.0), Vec3::UnitX(), 1000, 40, 2.7));
    net.addFilament(makeStraightFilament(0, Vec3(3200.0, 2100.0, 2000.0), -Vec3::UnitX(), 1000, 40, 2.7));
    // Sites facing each other across the 200 nm gap: 250 motor sites (of 2 monomers)
    // from filament 0's minus end is x = 1852; from filament 1's, x = 1848.
    Binding b;
    b.filament = {0, 1};
    b.site = {250, 250};
    b.rest_length = (net.sitePosition(BinderKind::kMotor, 0, 1, 250) - net.sitePosition(BinderKind::kMotor, 0, 0, 250)).norm();
    net.bind(BinderKind::kMotor, b);
  });
  for (int w = 1; w <= 400; ++w) {  // 20 s, far longer than the ~50 steps to stall
    rig.engine->advance(0.05 * w);
    rig.relaxed();
  }
  const Binding& b = rig.network->motors().front();
  const double step_tension = m.stiffness * 2.0 * 5.4;  // both ends one step: at most this much
  std::printf("[ measured ] stalled motor tension %.1f pN (stall force %.0f pN), ends moved %lld and %lld sites\n",
              b.tension, m.stall_force, static_cast<long long>(b.site[0] - 250), static_cast<long long>(b.site[1] - 250));
  EXPECT_GT(b.tension, m.stall_force - step_tension);
  EXPECT_LT(b.tension, m.stall_force + step_tension);
}

// Dimer nucleation "2 G -> filament" fires at k [G]^2 V: k / (N_A V) n (n - 1) per s.
TEST(FilamentNucleation, CreatesDimersAtTheMassActionRate) {
  FilamentConfig config;
  FilamentType t = inertActin();
  t.nucleation_rate = 1e-4;  // 1/(µM s)
  config.types = {t};
  const double size = 1000.0, T = 10.0;
  const double nv = copiesPerMicromolar(size * size * size);
  const int pool = 6000;
  Rig rig(size, {1, 1, 1}, {{"G", 0.0}}, {pool}, config, [](FilamentNetwork&) {});
  rig.engine->advance(T);
  const auto made = static_cast<double>(rig.network->filaments().size());
  const double expected = t.nucleation_rate / nv * pool * (pool - 1.0) * T;
  std::printf("[ measured ] %g nuclei in %g s, expected %.1f\n", made, T, expected);
  EXPECT_NEAR(made, expected, 4.0 * std::sqrt(expected) + 1.0);
  EXPECT_EQ(rig.total(0) + 2 * static_cast<int>(made), pool);
  for (const Filament& f : rig.network->filaments()) EXPECT_EQ(f.monomers(), 2);
}

// Branching consumes one Arp2/3 and one monomer; unbranching returns the complex, the
// daughter keeps its monomers: actin (free + polymer) and Arp2/3 (free + branches) are
// conserved through growth, branching, unbranching and shrinkage.
TEST(FilamentBranching, ConservesActinAndArp23) {
  FilamentConfig config;
  config.types = {filtest::actin()};
  BrancherType b;
  b.name = "arp";
  b.species = "A";
  b.species_index = 1;
  b.rate = 0.05;
  b.unbranch_rate = 0.5;
  config.branchers = {b};
  const int g0 = 3000, a0 = 200;
  Rig rig(1000.0, {2, 2, 2}, {{"G", 1e6}, {"A", 1e6}}, {g0, a0}, config, [](FilamentNetwork& net) {
    for (int i = 0; i < 5; ++i)
      net.addFilament(makeStraightFilament(0, Vec3(300.0, 300.0 + 250.0 * i, 1000.0), Vec3::UnitX(), 300, 40, 2.7));
  });
  long branched = 0;
  for (int w = 1; w <= 40; ++w) {
    rig.engine->advance(0.25 * w);
    rig.relaxed();
    long polymer = 0;
    for (const Filament& f : rig.network->filaments()) polymer += f.monomers();
    ASSERT_EQ(polymer + rig.total(0), g0 + 5 * 300);
    ASSERT_EQ(static_cast<int>(rig.network->branches().size()) + rig.total(1), a0);
    for (const Branch& br : rig.network->branches()) {
      const Filament& d = rig.network->filaments()[br.daughter];
      ASSERT_TRUE(d.minus_capped);
      // The daughter starts on its mother's site.
      const Vec3 site = rig.network->sitePosition(BinderKind::kBrancher, 0, br.mother, br.site);
      ASSERT_LT((d.beads.front() - site).norm(), 1e-9);
    }
    branched = std::max<long>(branched, static_cast<long>(rig.network->branches().size()));
  }
  EXPECT_GT(branched, 0);
  EXPECT_GT(rig.engine->reactionEvents()[rig.model.reactions.size() - 1], 0);  // unbranching happened
}

// A plus end shrinking past a bound linker's site releases the linker into the pool.
TEST(FilamentShrinkage, ReleasesLinkersItLosesTheSitesOf) {
  FilamentConfig config;
  FilamentType t = inertActin();
  t.plus_off = 20.0;
  config.types = {t};
  LinkerType l;
  l.name = "aa";
  l.species = "L";
  l.species_index = 1;
  l.on_rate = l.off_rate = 0.0;  // only shrinkage can free them
  config.linkers = {l};
  Rig rig(2000.0, {1, 1, 1}, {{"G", 0.0}, {"L", 0.0}}, {0, 0}, config, [&](FilamentNetwork& net) {
    net.addFilament(makeStraightFilament(0, Vec3(400.0, 1000.0, 1000.0), Vec3::UnitX(), 200, 40, 2.7));
    net.addFilament(makeStraightFilament(0, Vec3(400.0, 1035.0, 1000.0), Vec3::UnitX(), 200, 40, 2.7));
    for (std::int64_t site = 0; site < 20; ++site) {
      Binding b;
      b.filament = {0, 1};
      b.site = {site, site};
      b.rest_length = 35.0;
      net.bind(BinderKind::kLinker, b);
    }
  });
  rig.engine->advance(30.0);  // both filaments shrink to their two-monomer minimum
  for (const Filament& f : rig.network->filaments()) EXPECT_EQ(f.monomers(), 2);
  EXPECT_EQ(rig.network->linkers().size() + static_cast<std::size_t>(rig.total(1)), 20u);
  EXPECT_EQ(rig.network->linkers().size(), 0u);  // every site is gone
  EXPECT_EQ(rig.total(0), 2 * 198);
}

}  // namespace
}  // namespace cortex

namespace cortex {
namespace {

// A damaged checkpoint stops with an input error instead of crashing the run.
TEST(FilamentRestore, RefusesDamagedState) {
  FilamentConfig config;
  config.types = {filtest::actin()};
  LinkerType l;
  l.name = "aa";
  l.species_index = 1;
  config.linkers = {l};
  FilamentState good;
  good.filaments = {makeStraightFilament(0, Vec3(100, 100, 100), Vec3::UnitX(), 100, 40, 2.7),
                    makeStraightFilament(0, Vec3(100, 135, 100), Vec3::UnitX(), 100, 40, 2.7)};
  Binding b;
  b.filament = {0, 1};
  b.site = {3, 3};
  b.rest_length = 35.0;
  good.linkers = {b};
  EXPECT_NO_THROW(buildFilamentNetwork(config, Vec3::Zero(), Vec3::Constant(1000), 1, &good));
  auto expectRefused = [&](auto damage) {
    FilamentState s = good;
    damage(s);
    EXPECT_THROW(buildFilamentNetwork(config, Vec3::Zero(), Vec3::Constant(1000), 1, &s), InputError);
  };
  expectRefused([](FilamentState& s) { s.filaments[0].beads[1].x() = std::nan(""); });
  expectRefused([](FilamentState& s) { s.filaments[0].type = 7; });
  expectRefused([](FilamentState& s) { s.filaments[0].lattice[1] = s.filaments[0].lattice[0]; });
  expectRefused([](FilamentState& s) { s.linkers[0].type = 5; });
  expectRefused([](FilamentState& s) { s.linkers[0].site[1] = 1000000; });
  expectRefused([](FilamentState& s) { s.linkers[0].filament[1] = 0; });
  expectRefused([](FilamentState& s) { s.linkers.push_back(s.linkers[0]); });  // one site, two linkers
  expectRefused([](FilamentState& s) { s.branches.push_back({0, 0, 1, 2, 0}); });  // no brancher types
}

}  // namespace
}  // namespace cortex
