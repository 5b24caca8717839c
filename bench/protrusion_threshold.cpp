// The threshold for protrusion (issue 13's physics check, thesis section 2.3), a long
// scenario (~10 min on one core), so here and not in ctest. N filaments holding a tube,
// whose force is f₀ = 2π√(2κγ) whatever its length, lengthen it if together they out-pull
// it: with the load shared equally, k_on c exp(−f₀δ/(N kT)) ≥ k_off, i.e. above
// c* = (k_off/k_on) exp(f₀δ/(N kT)). A tube ~10 radii long is first pulled at 6 µM; the
// bundle's mean length is then followed for 2.5 s at c*/1.25 and 1.25 c* (after 0.5 s
// for the pool to settle), and the threshold is where the straight line through the two
// (velocity, measured mean concentration) points crosses zero. Reports it as a fraction
// of c* (the issue asks for 1 ± 0.25) beside both velocities and the mean total load.
// Results and their reading: docs/coupling.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "core/constants.hpp"
#include "io/config.hpp"
#include "sim/simulation.hpp"
#include "sim/system.hpp"
#include "tube_pulling.hpp"

namespace cortex {
namespace {

// Mean filament length (nm), total plus-end load (pN) and G copies after each relaxation
// past `after` seconds.
class BundleRecorder final : public RunObserver {
 public:
  explicit BundleRecorder(double after) : after_(after) {}
  void onWindow(const System& system, const MinimizationResult&) override {
    if (system.time() < after_) return;
    const FilamentNetwork& net = *system.filaments();
    double length = 0.0, load = 0.0;
    for (std::size_t f = 0; f < net.filaments().size(); ++f) {
      length += net.filaments()[f].monomers() * net.type(net.filaments()[f].type).monomer_size;
      load += system.filamentChemistry()->endLoad(static_cast<Index>(f), true);
    }
    double copies = 0.0;
    for (Index i = 0; i < system.chemistry()->numSubvolumes(); ++i) copies += system.chemistry()->copies(i, 0);
    times.push_back(system.time());
    lengths.push_back(length / static_cast<double>(net.filaments().size()));
    loads += load, g_copies += copies, ++windows;
  }
  double velocity() const {  // nm/s, least squares
    const double n = static_cast<double>(times.size());
    double st = 0, sl = 0, stt = 0, stl = 0;
    for (std::size_t i = 0; i < times.size(); ++i)
      st += times[i], sl += lengths[i], stt += times[i] * times[i], stl += times[i] * lengths[i];
    return (n * stl - st * sl) / (n * stt - st * st);
  }
  std::vector<double> times, lengths;
  double loads = 0.0, g_copies = 0.0;
  int windows = 0;

 private:
  double after_;
};

// The tube-pulling scenario (tube_pulling.hpp) on a 500 nm patch under tension
// 0.02 pN/nm (f₀ = 12.6 pN, tube radius 50 nm) with N filaments, seeded by N.
std::string config(int filaments, double concentration, double on, double off, double window, double end_time) {
  bench::TubePulling s;
  s.seed = static_cast<unsigned>(filaments);
  s.end_time = end_time, s.window = window, s.patch = 500.0;
  s.filaments = filaments, s.concentration = concentration, s.on = on, s.off = off;
  return bench::tubePullingConfig(s);
}

void BM_ProtrusionThreshold(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double kT = constants::kBoltzmann * 298.15, delta = 2.7, f0 = 2 * M_PI * std::sqrt(2 * 100.0 * 0.02);
  // Fast ends (k_on 580 /(µM·s), k_off 29 /s, 50× actin's) so that the drift at ±25%
  // (≈ δ k_off · 0.25 = 20 nm/s with equal sharing) stands clear of the noise of the mean
  // length over 2.5 s (~5 nm/s); windows of 2 ms hold < 0.1 events per end.
  const double on = 580.0, off = 29.0, threshold = off / on * std::exp(f0 * delta / (n * kT));
  const double copies_per_uM = kCopiesPerMicromolarFemtoliter * 1.0;  // the 1 µm cube
  double c[2] = {}, v[2] = {}, load = 0.0;
  for (auto _ : state) {
    const Config grow = parseConfig(config(n, 6.0, 116.0, 5.8, 0.01, 1.5), "grow.toml", ".", {});
    System tube(grow);
    RunObserver quiet;
    Simulation(tube, grow.simulation, grow.mechanics, quiet).run(true);
    for (int k = 0; k < 2; ++k) {
      const Config follow =
          parseConfig(config(n, (k ? 1.25 : 0.8) * threshold, on, off, 0.002, 4.5), "follow.toml", ".", {});
      System system(follow, &static_cast<const SystemState&>(tube.state()));
      system.step = std::llround(system.time() / follow.simulation.chemistry_window);  // windows of the new size
      BundleRecorder recorder(2.0);
      Simulation(system, follow.simulation, follow.mechanics, recorder).run(false);
      v[k] = recorder.velocity();
      c[k] = recorder.g_copies / recorder.windows / copies_per_uM / threshold;
      load += recorder.loads / recorder.windows / 2;
    }
  }
  state.counters["c_star_uM"] = threshold;
  state.counters["c_low_over_c_star"] = c[0];
  state.counters["v_low_nm_s"] = v[0];
  state.counters["c_high_over_c_star"] = c[1];
  state.counters["v_high_nm_s"] = v[1];
  state.counters["threshold_over_c_star"] = c[0] - v[0] * (c[1] - c[0]) / (v[1] - v[0]);
  state.counters["mean_load_over_f0"] = load / f0;
}
BENCHMARK(BM_ProtrusionThreshold)->Arg(7)->Arg(10)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace cortex

BENCHMARK_MAIN();
