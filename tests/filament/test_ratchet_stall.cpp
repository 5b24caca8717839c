// The Brownian ratchet (thesis eq. 2.14) end to end: an anchored filament polymerizing
// against a soft wall stalls where the wall's load f satisfies
// k_on c exp(-f delta / kT) = k_off, i.e. at f = kT/delta ln(k_on c / k_off), with the
// load measured after each relaxation as the real loop computes it.
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "filament/boundary_energy.hpp"
#include "sim/simulation.hpp"

namespace cortex {
namespace {

// Records the wall force on the plus end after every relaxation past `after` seconds.
class LoadRecorder final : public RunObserver {
 public:
  explicit LoadRecorder(double after) : after_(after) {}
  void onWindow(const System& system, const MinimizationResult& r) override {
    if (system.time() < after_) return;
    const FilamentNetwork& net = *system.filaments();
    const Filament& f = net.filaments().front();
    loads.push_back(-boundaryForce(*net.config().boundary, f.beads.back()).dot(f.plusDirection()));
    converged = converged && r.converged;
  }
  std::vector<double> loads;
  bool converged = true;

 private:
  double after_;
};

// One anchored filament growing along +x towards a soft wall at x = 1000 nm, in 1 µM of
// monomers in a 5 µm cube (75,277 copies: growth to stall takes ~50, so the pool is
// buffered); k_on c / k_off = 20.
Config wallConfig(double end_time, double window) {
  Config config;
  config.source = "ratchet test";
  config.simulation.seed = 11;
  config.simulation.end_time = end_time;
  config.simulation.chemistry_window = window;
  config.simulation.snapshot_interval = end_time;
  config.mechanics.force_tolerance = 0.01;
  ChemistryConfig chemistry;
  chemistry.grid = {5000.0, {1, 1, 1}};
  chemistry.species = {{"G", 0.0}};
  chemistry.initial_copies = {75277};
  chemistry.sides = {{}};
  config.chemistry = chemistry;
  FilamentType actin;
  actin.monomer_species = "G";
  actin.monomer_species_index = 0;
  actin.plus_on = 11.6, actin.plus_off = 0.58, actin.minus_on = 1.3, actin.minus_off = 0.8;
  FilamentInit bundle;
  bundle.type = actin.name;
  bundle.length = 405.0;
  bundle.placement = FilamentInit::Placement::kBundle;
  bundle.center = Vec3(702.5, 500.0, 500.0);
  bundle.direction = Vec3::UnitX();
  bundle.fixed_minus_end = true;
  BoundaryConfig wall;
  wall.max = Vec3(1000.0, 1000.0, 1000.0);
  wall.repulsion = 56.0;
  wall.screening_length = 20.0;
  config.filaments = FilamentConfig{{actin}, {bundle}, {}, {}, {}, wall};
  return config;
}

// The ratchet law's stall force for wallConfig's filament: (kT/δ) ln(k_on c / k_off).
double stallForce() {
  const double kT = constants::kBoltzmann * 298.15, delta = 2.7;
  const double c = 75277.0 / (kCopiesPerMicromolarFemtoliter * 125.0);
  return kT / delta * std::log(11.6 * c / 0.58);
}

TEST(FilamentRatchet, StallsAtTheRatchetForceAgainstAWall) {
  const Config config = wallConfig(1000.0, 0.02);
  auto system = std::make_unique<System>(config);
  LoadRecorder recorder(20.0);  // stall is reached within ~5 s
  Simulation sim(*system, config.simulation, config.mechanics, recorder);
  sim.run(true);
  ASSERT_GT(recorder.loads.size(), 1000u);
  EXPECT_TRUE(recorder.converged);
  double mean = 0.0;
  for (double f : recorder.loads) mean += f;
  mean /= static_cast<double>(recorder.loads.size());
  const double stall = stallForce();
  std::printf("[ measured ] mean wall load at stall %.3f pN, ratchet law %.3f pN (%+.1f%%), %zu windows\n", mean,
              stall, 100.0 * (mean / stall - 1.0), recorder.loads.size());
  EXPECT_NEAR(mean, stall, 0.10 * stall);  // the acceptance criterion
  // The anchored minus end never moved.
  EXPECT_NEAR(system->filaments()->filaments().front().beads.front().x(), 500.0, 1e-9);
}

// The default wall (F0 = 41 pN, λ = 2.7 nm, MEDYAN's) grows e-fold over one monomer. An
// end weighed by the load at its site stalled at 1.6-1.7 x the ratchet force there (the
// loads of the sites it visits spread over factors of e, and e^{-f δ/kT} averaged to
// 1/(k_on c/k_off) puts the mean far above); weighed by the step's energy change it
// stalls at the ratchet force. The exact Markov chain of that rule gives the ratchet force
// within ±2.4% over the lattice phases for a rigid filament; this one's axial compliance
// (~25 pN/nm) lowers it by 2-5% (the step's energy is taken with the filament held).
// Pooled over four lattice phases, 3000 s each (SE of the pooled mean ~2%): within 10%.
TEST(FilamentRatchet, StallsAtTheRatchetForceAgainstTheDefaultSteepWall) {
  const double delta = 2.7, stall = stallForce();
  double pooled = 0.0;
  std::size_t samples = 0;
  for (double phase : {0.0, 0.25, 0.5, 0.75}) {
    Config config = wallConfig(3000.0, 0.02);
    config.filaments->boundary->repulsion = BoundaryConfig{}.repulsion;
    config.filaments->boundary->screening_length = BoundaryConfig{}.screening_length;
    config.filaments->initial.front().center.x() += phase * delta;
    auto system = std::make_unique<System>(config);
    LoadRecorder recorder(20.0);
    Simulation sim(*system, config.simulation, config.mechanics, recorder);
    sim.run(true);
    ASSERT_GT(recorder.loads.size(), 1000u);
    double mean = 0.0;
    for (double f : recorder.loads) mean += f;
    pooled += mean;
    samples += recorder.loads.size();
    mean /= static_cast<double>(recorder.loads.size());
    std::printf("[ measured ] default wall, lattice phase %.2f: mean load at stall %.3f pN (%+.1f%%)\n", phase, mean,
                100.0 * (mean / stall - 1.0));
  }
  pooled /= static_cast<double>(samples);
  std::printf("[ measured ] default wall, pooled: %.3f pN, ratchet law %.3f pN (%+.1f%%)\n", pooled, stall,
              100.0 * (pooled / stall - 1.0));
  EXPECT_NEAR(pooled, stall, 0.10 * stall);
}

// Within one window of 30 s (no relaxation after the first) the end's wall load follows
// it event by event (WallEndLoads): it stalls where the ratchet law says, instead of
// growing on at the load of the last relaxation (~0.5 pN, which let it run ~1 µm through
// the wall before the walls joined the probe). The end's mean wall load over the second
// half of the window, sampled in 30 windows of 1 s after one long one would not show
// it, so: the final tip in 10 runs of one window each, seeds 1–10.
TEST(FilamentRatchet, AnEndStallsAtTheWallWithinOneLongWindow) {
  const double stall = stallForce();
  double mean = 0.0, furthest = 0.0;
  for (unsigned seed = 1; seed <= 10; ++seed) {
    Config config = wallConfig(30.0, 30.0);
    config.simulation.seed = seed;
    auto system = std::make_unique<System>(config);
    RunObserver quiet;
    Simulation sim(*system, config.simulation, config.mechanics, quiet);
    sim.run(true);
    const FilamentNetwork& net = *system->filaments();
    const Filament& f = net.filaments().front();
    mean += -boundaryForce(*net.config().boundary, f.beads.back()).dot(f.plusDirection()) / 10.0;
    furthest = std::max(furthest, f.beads.back().x());
  }
  std::printf("[ measured ] wall load after one 30 s window %.3f pN (mean of 10), ratchet law %.3f pN; "
              "furthest tip x = %.1f nm\n", mean, stall, furthest);
  EXPECT_LT(furthest, 1000.0) << "an end grew through the wall";
  EXPECT_NEAR(mean, stall, 0.25 * stall);  // 10 single samples of a load that steps by 14% per monomer
}

}  // namespace
}  // namespace cortex
