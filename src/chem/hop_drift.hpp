// How a potential biases a hop along an edge whose ends differ by x = β(h_j − h_i)
// (thesis 3.2.2; docs/proteins.md): the free rate is multiplied by
//   exponential (Scharfetter–Gummel): B(x) = x / (eˣ − 1), exact for the Boltzmann
//     distribution at any x, since B(−x) = eˣ B(x);
//   linear: 1 − x/2, its first-order expansion, whose rates turn negative past |x| = 2:
//     such edges are closed in both directions (the thesis' clipping, made symmetric so
//     the stationary state stays Boltzmann on the remaining edges).
#pragma once

#include <algorithm>
#include <cmath>

namespace cortex {

enum class DriftScheme { kExponential, kLinear };

// B(x), evaluated without expm1, which took 40% of a phase-separation run
// (examples/membrane_llps.toml): for |x| < 1/2 by its Taylor series Σ B_n xⁿ/n! with
// the Bernoulli numbers B_n up to x¹⁴ (the first term left out is below 10⁻¹⁷), beyond
// as x / (eˣ − 1) with exp: there |eˣ − 1| ≥ 0.39, so exp's rounding grows at most
// 2.6-fold in the difference. Within 4 ulp of the exact value either way
// (tests/chem/test_hop_drift.cpp).
inline double exponentialDrift(double x) {
  if (std::abs(x) < 0.5) {
    const double y = x * x;
    const double even =
        1.0 + y * (1.0 / 12 +
                   y * (-1.0 / 720 +
                        y * (1.0 / 30240 +
                             y * (-1.0 / 1209600 +
                                  y * (1.0 / 47900160 + y * (-691.0 / 1307674368000 + y * (1.0 / 74724249600)))))));
    return even - 0.5 * x;
  }
  return x / (std::exp(x) - 1.0);
}

// The linear factor of a hop at x whose reverse is at `reverse` (−x when the energies
// are those of one state; curvature sensing's arrival and leaving energies differ).
inline double linearDrift(double x, double reverse) {
  return std::max(std::abs(x), std::abs(reverse)) >= 2.0 ? 0.0 : 1.0 - 0.5 * x;
}

}  // namespace cortex
