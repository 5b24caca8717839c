// Filament chemistry against closed forms: elongation in a buffered pool, the critical
// concentration of a finite pool, and the binding equilibrium of cross-linkers on fixed
// filaments. No mechanics: positions change only by growth.
#include <gtest/gtest.h>

#include <cmath>

#include "../chem/chem_statistics.hpp"
#include "filament_fixtures.hpp"

namespace cortex {
namespace {

using filtest::Rig;

// A pool so large that growth hardly depletes it: each end elongates at
// delta-free rate k_on c - k_off monomers/s (here counted in monomers, so the
// length rate is monomer_size times that).
TEST(FilamentChemistry, ElongationRateInBufferedPoolMatchesEndRates) {
  const double size = 5000.0, c0 = 10.0, T = 5.0;
  const int filaments = 20, start = 100;
  const double nv = copiesPerMicromolar(size * size * size);
  FilamentConfig config;
  config.types = {filtest::actin()};
  const int pool = static_cast<int>(std::lround(c0 * nv));
  Rig rig(size, {1, 1, 1}, {{"G", 0.0}}, {pool}, config, [&](FilamentNetwork& net) {
    for (int i = 0; i < filaments; ++i)
      net.addFilament(makeStraightFilament(0, Vec3(1000.0, 200.0 + 200.0 * i, 2500.0), Vec3::UnitX(), start, 40, 2.7));
  });
  rig.engine->advance(T);
  const int left = rig.total(0);
  // The pool fell linearly by ~2%: the mean concentration over the run sets the rate.
  const double c = 0.5 * (pool + left) / nv;
  const FilamentType t = filtest::actin();
  double plus = 0.0, minus = 0.0;
  for (const Filament& f : rig.network->filaments()) {
    plus += static_cast<double>(f.plusEnd() - start);
    minus += static_cast<double>(-f.minusEnd());
  }
  plus /= filaments, minus /= filaments;
  const double plus_expected = T * (t.plus_on * c - t.plus_off), minus_expected = T * (t.minus_on * c - t.minus_off);
  // Each end is a birth-death process: variance T (k_on c + k_off) per filament.
  const double plus_sd = std::sqrt(T * (t.plus_on * c + t.plus_off) / filaments);
  const double minus_sd = std::sqrt(T * (t.minus_on * c + t.minus_off) / filaments);
  RecordProperty("plus_growth", std::to_string(plus) + " vs " + std::to_string(plus_expected));
  std::printf("[ measured ] plus end %.1f vs %.1f +- %.1f monomers, minus end %.1f vs %.1f +- %.1f in %g s\n", plus,
              plus_expected, plus_sd, minus, minus_expected, minus_sd, T);
  EXPECT_NEAR(plus, plus_expected, 4.0 * plus_sd);
  EXPECT_NEAR(minus, minus_expected, 4.0 * minus_sd);
  // Every monomer on a filament came out of the pool.
  long polymer = 0;
  for (const Filament& f : rig.network->filaments()) polymer += f.monomers();
  EXPECT_EQ(polymer + left, static_cast<long>(filaments) * start + pool);
  // Length follows the lattice: cylinders of 40 monomers, the ends partial.
  for (const Filament& f : rig.network->filaments())
    EXPECT_NEAR(f.length(), 2.7 * static_cast<double>(f.monomers()), 1e-6 * f.length());
}

// With a finite pool, free monomers relax to the critical concentration
// c_c = (k+off + k-off) / (k+on + k-on); the stationary copy number is exactly Poisson
// with mean c_c N V (detailed balance of n <-> n - 1 at rates k_on n / (N V) and k_off,
// as long as the filament never reaches its minimum size).
TEST(FilamentChemistry, FreeMonomersRelaxToCriticalConcentration) {
  const double size = 500.0;
  const double nv = copiesPerMicromolar(size * size * size);
  FilamentConfig config;
  config.types = {filtest::actin()};
  const int pool = 1000, start = 100;
  Rig rig(size, {1, 1, 1}, {{"G", 0.0}}, {pool}, config, [&](FilamentNetwork& net) {
    net.addFilament(makeStraightFilament(0, Vec3(100.0, 250.0, 250.0), Vec3::UnitX(), start, 40, 2.7));
  });
  const FilamentType t = filtest::actin();
  const double critical = (t.plus_off + t.minus_off) / (t.plus_on + t.minus_on);
  const double mean = critical * nv;
  // Relaxation time N V / (k+on + k-on) ~ 6 s: burn in 20 of them, sample every 5 of them.
  const double tau = nv / (t.plus_on + t.minus_on);
  double time = 20.0 * tau;
  rig.engine->advance(time);
  std::vector<int> samples;
  for (int i = 0; i < 800; ++i) {
    time += 5.0 * tau;
    rig.engine->advance(time);
    samples.push_back(rig.total(0));
  }
  const auto m = chemtest::moments(samples);
  std::printf("[ measured ] free monomers %.2f +- %.2f (critical %.2f copies = %.4f uM), variance %.2f\n", m.mean,
              m.standardError, mean, critical, m.variance);
  EXPECT_NEAR(m.mean, mean, 4.0 * m.standardError);
  const auto fit = chemtest::goodnessOfFit(samples, [&](int n) {
    return std::exp(n * std::log(mean) - mean - std::lgamma(n + 1.0));
  });
  EXPECT_GT(fit.p, 1e-4) << "chi2 " << fit.statistic << " dof " << fit.dof;
  EXPECT_EQ(rig.network->filaments()[0].monomers() + rig.total(0), pool + start);
}

// Linkers on two fixed parallel filaments 35 nm apart with binding range 30-40 nm: site
// j pairs only with site j opposite (the diagonal is 44 nm), so there are N independent
// pairs and L + P <-> LP with exact stationary law
//   P(b) ∝ K^b / (b! (L - b)! (N - b)!),  K = (k_on / N_A V) / k_off.
TEST(FilamentChemistry, LinkerBoundFractionMatchesBindingEquilibrium) {
  const double size = 2000.0;
  const double nv = copiesPerMicromolar(size * size * size);
  FilamentConfig config;
  FilamentType t = filtest::actin();
  t.plus_on = t.plus_off = t.minus_on = t.minus_off = 0.0;
  config.types = {t};
  LinkerType l;
  l.name = "aa";
  l.species = "L";
  l.species_index = 1;
  l.on_rate = 40.0;  // 1/(µM s) per pair
  l.off_rate = 0.3;
  config.linkers = {l};
  const int linkers = 60, monomers = 400;
  Rig rig(size, {1, 1, 1}, {{"G", 0.0}, {"L", 0.0}}, {0, linkers}, config, [&](FilamentNetwork& net) {
    net.addFilament(makeStraightFilament(0, Vec3(400.0, 1000.0, 1000.0), Vec3::UnitX(), monomers, 40, 2.7));
    net.addFilament(makeStraightFilament(0, Vec3(400.0, 1035.0, 1000.0), Vec3::UnitX(), monomers, 40, 2.7));
  });
  const int pairs = monomers / l.site_spacing;
  const double K = l.on_rate / nv / l.off_rate;
  std::vector<double> weight(std::min(linkers, pairs) + 1);
  double norm = 0.0, exact = 0.0;
  for (int b = 0; b < static_cast<int>(weight.size()); ++b) {
    weight[b] = std::exp(b * std::log(K) - std::lgamma(b + 1.0) - std::lgamma(linkers - b + 1.0) -
                         std::lgamma(pairs - b + 1.0));
    norm += weight[b];
  }
  for (int b = 0; b < static_cast<int>(weight.size()); ++b) exact += b * weight[b] / norm;
  // Relaxation is ~1/k_off = 3 s; samples 15 s apart are independent.
  double time = 60.0;
  rig.engine->advance(time);
  std::vector<int> bound;
  for (int i = 0; i < 1000; ++i) {
    time += 15.0;
    rig.engine->advance(time);
    bound.push_back(static_cast<int>(rig.network->linkers().size()));
    ASSERT_EQ(bound.back() + rig.total(1), linkers);
  }
  const auto m = chemtest::moments(bound);
  std::printf("[ measured ] bound linkers %.2f +- %.2f of %d pairs; exact %.2f\n", m.mean, m.standardError, pairs,
              exact);
  EXPECT_NEAR(m.mean, exact, 4.0 * m.standardError);
  const auto fit = chemtest::goodnessOfFit(bound, [&](int b) {
    return b < static_cast<int>(weight.size()) ? weight[b] / norm : 0.0;
  });
  EXPECT_GT(fit.p, 1e-4) << "chi2 " << fit.statistic << " dof " << fit.dof;
  // Every bound linker sits on a pair of opposite sites, each site at most once.
  for (const Binding& b : rig.network->linkers()) {
    EXPECT_EQ(b.site[0], b.site[1]);
    EXPECT_NEAR(b.rest_length, 35.0, 1e-9);
  }
}

}  // namespace
}  // namespace cortex
