// The hop factors of chem/hop_drift.hpp: the exponential (Scharfetter–Gummel) factor
// B(x) = x / (eˣ − 1) against an extended-precision reference, and the identity that
// makes its stationary state Boltzmann.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "chem/hop_drift.hpp"

namespace cortex {
namespace {

// x / expm1(x) in long double (64-bit mantissa on x86-64: 11 bits beyond double).
long double referenceDrift(long double x) { return x == 0.0L ? 1.0L : x / std::expm1l(x); }

// Arguments across both forms (the series below |x| = 1/2, expm1 beyond), at the
// boundary, and tiny ones.
std::vector<double> arguments() {
  std::vector<double> xs;
  for (int k = -3000; k <= 3000; ++k) xs.push_back(k * 1e-3);
  for (double x : {0.5, std::nextafter(0.5, 0.0), -0.5, std::nextafter(-0.5, 0.0), 1e-300, -1e-300, 1e-13, -1e-13,
                   30.0, -30.0, 700.0})
    xs.push_back(x);
  return xs;
}

TEST(HopDrift, ExponentialFactorMatchesExtendedPrecision) {
  // 4 ulp: the series' Horner evaluation and the division each round; the truncation
  // (first term left out ~5e-18 at |x| = 1/2) is below one.
  const double tolerance = 4.0 * std::numeric_limits<double>::epsilon();
  double worst = 0.0;
  for (double x : arguments()) {
    const long double ref = referenceDrift(x);
    const double err = static_cast<double>(std::fabs((exponentialDrift(x) - ref) / ref));
    worst = std::max(worst, err);
    ASSERT_LE(err, tolerance) << "x = " << x;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(HopDrift, ExponentialFactorKeepsDetailedBalance) {
  // B(−x) = eˣ B(x): the forward and backward rates of an edge stand in the Boltzmann
  // ratio, whichever form evaluates each.
  for (double x : arguments()) {
    if (std::abs(x) > 30.0) continue;  // eˣ B(x) under- or overflows there
    const double lhs = exponentialDrift(-x), rhs = std::exp(x) * exponentialDrift(x);
    ASSERT_NEAR(lhs / rhs, 1.0, 8.0 * std::numeric_limits<double>::epsilon()) << "x = " << x;
  }
}

TEST(HopDrift, LinearFactorClosesBothDirectionsPastTwo) {
  EXPECT_DOUBLE_EQ(linearDrift(1.0, -1.0), 0.5);
  EXPECT_DOUBLE_EQ(linearDrift(-1.0, 1.0), 1.5);
  EXPECT_EQ(linearDrift(2.5, -2.5), 0.0);
  EXPECT_EQ(linearDrift(-2.5, 2.5), 0.0);  // the reverse of a closed edge is closed too
  EXPECT_EQ(linearDrift(0.5, -2.0), 0.0);  // closed by its reverse alone
}

}  // namespace
}  // namespace cortex
