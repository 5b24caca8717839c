// Stationary distributions with closed forms (docs/chemistry.md), run on both
// engines. Stochastic tests with fixed seeds.
//
// Occupancy is sampled at fixed times, an unbiased estimate of the time-averaged
// occupancy; samples are spaced at least 5 relaxation times apart (autocorrelation
// below e^-5 ≈ 0.007; the measured lag-1 autocorrelation is checked below 0.05, i.e.
// within 5 standard errors of a correlation estimate from 10^4 samples), so they are
// independent and the statistics have their nominal distributions. Tolerances: means
// and variances within 5 standard errors, chi-square goodness of fit with p > 1e-4.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "chem_models.hpp"
#include "chem_statistics.hpp"

namespace cortex {
namespace {


class Stationary : public ::testing::TestWithParam<EngineKind> {};

double poisson(double mean, int n) { return std::exp(n * std::log(mean) - mean - std::lgamma(n + 1.0)); }

double binomial(int trials, double p, int n) {
  if (n > trials) return 0.0;
  return std::exp(std::lgamma(trials + 1.0) - std::lgamma(n + 1.0) - std::lgamma(trials - n + 1.0) + n * std::log(p) +
                  (trials - n) * std::log1p(-p));
}

// -> A at k1, A -> at k2: Poisson(k1·N·V / k2).
TEST_P(Stationary, BirthDeathIsPoisson) {
  const double mean = 20.0, k2 = 1.0;
  ChemistryModel m = chemtest::wellMixed({"A"}, {{"-> A", 0.0}, {"A ->", k2}});
  m.reactions[0].rate = mean * k2 / copiesPerMicromolar(m.volumes.size[0]);
  auto engine = makeChemistryEngine(GetParam(), m, {0}, 11);
  engine->advance(10.0);
  const std::vector<int> n = chemtest::sample(*engine, 5.0 / k2, 20000, [](const auto& e) { return e.copies(0, 0); });

  EXPECT_LT(std::abs(chemtest::lagOneCorrelation(n)), 0.05);
  const chemtest::Moments mo = chemtest::moments(n);
  EXPECT_NEAR(mo.mean, mean, 5.0 * mo.standardError);
  EXPECT_NEAR(mo.variance, mean, 5.0 * mo.varianceError);
  const chemtest::ChiSquare fit = chemtest::goodnessOfFit(n, [&](int k) { return poisson(mean, k); });
  EXPECT_GT(fit.p, 1e-4) << "chi2 " << fit.statistic << " dof " << fit.dof;
}

// A -> B at kf, B -> A at kb, N copies in all: B ~ Binomial(N, kf / (kf + kb)).
TEST_P(Stationary, IsomerizationIsBinomial) {
  const int copies = 40;
  const double kf = 1.0, kb = 3.0, p = kf / (kf + kb);
  const ChemistryModel m = chemtest::wellMixed({"A", "B"}, {{"A -> B", kf}, {"B -> A", kb}});
  auto engine = makeChemistryEngine(GetParam(), m, {copies, 0}, 12);
  engine->advance(5.0);
  const std::vector<int> b =
      chemtest::sample(*engine, 6.0 / (kf + kb), 20000, [](const auto& e) { return e.copies(0, 1); });

  EXPECT_LT(std::abs(chemtest::lagOneCorrelation(b)), 0.05);
  const chemtest::Moments mo = chemtest::moments(b);
  EXPECT_NEAR(mo.mean, copies * p, 5.0 * mo.standardError);
  EXPECT_NEAR(mo.variance, copies * p * (1 - p), 5.0 * mo.varianceError);
  const chemtest::ChiSquare fit = chemtest::goodnessOfFit(b, [&](int k) { return binomial(copies, p, k); });
  EXPECT_GT(fit.p, 1e-4) << "chi2 " << fit.statistic << " dof " << fit.dof;
}

// A + B -> C (propensity c1·n_A·n_B), C -> A + B (c2·n_C) from A0, B0 copies:
// p(n_C) ∝ K^n_C / (n_C! (A0 - n_C)! (B0 - n_C)!), K = c1/c2. Mean about 10, relaxation
// rate about c1·(n_A + n_B) + c2 = 2.5/s, samples 2.5 s apart.
TEST_P(Stationary, BindingMatchesClosedForm) {
  const int a0 = 30, b0 = 20;
  const double c1 = 0.05, c2 = 1.0, k = c1 / c2;
  ChemistryModel m = chemtest::wellMixed({"A", "B", "C"}, {{"A + B -> C", 0.0}, {"C -> A + B", c2}});
  m.reactions[0].rate = c1 * copiesPerMicromolar(m.volumes.size[0]);
  std::vector<double> p(b0 + 1);
  double norm = 0.0;
  for (int n = 0; n <= b0; ++n) {
    p[n] = std::exp(n * std::log(k) - std::lgamma(n + 1.0) - std::lgamma(a0 - n + 1.0) - std::lgamma(b0 - n + 1.0));
    norm += p[n];
  }
  double exact = 0.0;
  for (int n = 0; n <= b0; ++n) exact += n * (p[n] /= norm);

  auto engine = makeChemistryEngine(GetParam(), m, {a0, b0, 0}, 14);
  engine->advance(5.0);
  const std::vector<int> c = chemtest::sample(*engine, 2.5, 20000, [](const auto& e) { return e.copies(0, 2); });
  EXPECT_LT(std::abs(chemtest::lagOneCorrelation(c)), 0.05);
  const chemtest::Moments mo = chemtest::moments(c);
  EXPECT_NEAR(mo.mean, exact, 5.0 * mo.standardError) << "exact mean " << exact;
  const chemtest::ChiSquare fit = chemtest::goodnessOfFit(c, [&](int n) { return n <= b0 ? p[n] : 0.0; });
  EXPECT_GT(fit.p, 1e-4) << "chi2 " << fit.statistic << " dof " << fit.dof;
  EXPECT_EQ(engine->copies(0, 0) - engine->copies(0, 1), a0 - b0);  // A - B is conserved
}

// Stationary distribution of -> A (rate `inflow` copies/s) and 2 A -> (propensity
// c·n(n-1)), from the chemical master equation truncated at n_max: solve p·Q = 0 with
// the normalization replacing one balance equation.
std::vector<double> dimerDecayDistribution(double inflow, double c, int n_max) {
  const int size = n_max + 1;
  Eigen::MatrixXd q = Eigen::MatrixXd::Zero(size, size);  // generator, rows = from
  for (int n = 0; n <= n_max; ++n) {
    if (n < n_max) {
      q(n, n + 1) += inflow;
      q(n, n) -= inflow;
    }
    if (n >= 2) {
      q(n, n - 2) += c * n * (n - 1);
      q(n, n) -= c * n * (n - 1);
    }
  }
  Eigen::MatrixXd a = q.transpose();
  a.row(0).setOnes();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
  rhs(0) = 1.0;
  const Eigen::VectorXd p = a.fullPivLu().solve(rhs);
  return std::vector<double>(p.data(), p.data() + size);
}

// 2 A -> with the header's propensity k/(N·V)·n(n-1), fed by -> A: the stationary mean
// against the master equation (truncated at 200 copies, where p < 1e-40).
TEST_P(Stationary, DimerDecayWithInflowMatchesMasterEquation) {
  const double inflow = 100.0, c = 0.1;  // copies/s; per pair and s
  ChemistryModel m = chemtest::wellMixed({"A"}, {{"-> A", 0.0}, {"2 A ->", 0.0}});
  const double nv = copiesPerMicromolar(m.volumes.size[0]);
  m.reactions[0].rate = inflow / nv;
  m.reactions[1].rate = c * nv;
  const std::vector<double> p = dimerDecayDistribution(inflow, c, 200);
  ASSERT_LT(p.back(), 1e-40);
  double exact = 0.0;
  for (std::size_t n = 0; n < p.size(); ++n) exact += n * p[n];

  auto engine = makeChemistryEngine(GetParam(), m, {0}, 13);
  engine->advance(5.0);
  // Relaxation rate about 4·c·mean ≈ 9/s: samples 1 s apart are independent.
  const std::vector<int> n = chemtest::sample(*engine, 1.0, 10000, [](const auto& e) { return e.copies(0, 0); });
  EXPECT_LT(std::abs(chemtest::lagOneCorrelation(n)), 0.05);
  const chemtest::Moments mo = chemtest::moments(n);
  EXPECT_NEAR(mo.mean, exact, 5.0 * mo.standardError) << "exact mean " << exact;
  const chemtest::ChiSquare fit = chemtest::goodnessOfFit(n, [&](int k) { return k < 201 ? p[k] : 0.0; });
  EXPECT_GT(fit.p, 1e-4) << "chi2 " << fit.statistic << " dof " << fit.dof;
}

INSTANTIATE_TEST_SUITE_P(Engines, Stationary, ::testing::Values(EngineKind::kNextSubvolume, EngineKind::kDirect),
                         [](const auto& info) { return std::string(chemtest::engineName(info.param)); });

}  // namespace
}  // namespace cortex
