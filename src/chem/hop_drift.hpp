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

// B(x), with its limit 1 at x = 0 (expm1 keeps it accurate for small |x|).
inline double exponentialDrift(double x) { return std::abs(x) < 1e-12 ? 1.0 - 0.5 * x : x / std::expm1(x); }

// The linear factor of a hop at x whose reverse is at `reverse` (−x when the energies
// are those of one state; curvature sensing's arrival and leaving energies differ).
inline double linearDrift(double x, double reverse) {
  return std::max(std::abs(x), std::abs(reverse)) >= 2.0 ? 0.0 : 1.0 - 0.5 * x;
}

}  // namespace cortex
