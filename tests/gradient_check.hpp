// The finite-difference harness every energy term's gradient is checked with.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mech/energy_term.hpp"

namespace cortex::testing {

// Relative error ||g_fd - g|| / ||g|| of `term`'s analytic gradient at x, g_fd by central
// differences of step h over every coordinate. Also checks that evaluate() adds to the
// gradient it is handed and writes nothing outside coordinates [begin, end), and that the
// gradient is not zero (which would make the comparison vacuous).
inline double gradientError(EnergyTerm& term, std::vector<double> x, double h, std::size_t begin = 0,
                            std::size_t end = static_cast<std::size_t>(-1)) {
  std::vector<double> g(x.size());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double& v : g) v = u(rng);
  const std::vector<double> g_before = g;
  std::uint64_t version = 1;
  term.evaluate({x.data(), g.data(), version++});
  for (std::size_t i = 0; i < g.size(); ++i) {
    g[i] -= g_before[i];
    if (i < begin || i >= end) {
      EXPECT_EQ(g[i], 0.0) << term.name() << " wrote coordinate " << i << ", not its own";
    }
  }
  double diff2 = 0.0, norm2 = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double x0 = x[i];
    x[i] = x0 + h;
    const double ep = term.evaluate({x.data(), nullptr, version++});
    x[i] = x0 - h;
    const double em = term.evaluate({x.data(), nullptr, version++});
    x[i] = x0;
    const double fd = (ep - em) / (2.0 * h);
    diff2 += (fd - g[i]) * (fd - g[i]);
    norm2 += g[i] * g[i];
  }
  EXPECT_GT(norm2, 0.0) << term.name() << " has a zero gradient: the test would be vacuous";
  return std::sqrt(diff2 / norm2);
}

}  // namespace cortex::testing
