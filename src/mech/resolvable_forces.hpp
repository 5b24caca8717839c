// Stiffnesses a relaxation cannot resolve. A minimizer stops when every force is below
// the force tolerance, and it reads forces as differences of energies and positions held
// in double precision: a stiffness whose natural force scale exceeds the tolerance by
// many orders cannot be relaxed to it. Measured on a 1,556-vertex vesicle (mesh 60 nm,
// tolerance 0.1 pN): bending_modulus 1e8 pN·nm (κ/h ≈ 1.7e6 pN) relaxes; 1e9 "converges"
// in the relaxation's own coordinates and leaves 58 pN at the final positions, 1e300
// spent 30 s before failing. Such a value is a unit slip, not a physical membrane or
// filament (100 pN·nm ≈ 24 k_BT is typical), so the input is refused up front. The
// callers choose the scale: the membrane's bending at a curvature of 1/h (where the
// failures above were measured), strain-held terms at 1% strain.
#pragma once

#include <string>

namespace cortex {

// How far a force scale may exceed the tolerance: 1e7, a decade under the measured
// failure above and 100x above the most demanding default (a 14k-vertex vesicle's own
// tolerance ~1e-4 pN against κ/h ≈ 7 pN).
inline constexpr double kMaxForceScaleOverTolerance = 1e7;

// Empty when force_scale (pN; `scale_formula` says how it was formed, e.g.
// "bending_modulus / mesh_size") is at most kMaxForceScaleOverTolerance × tolerance (pN);
// else the problem, for a message that names the key first. `tolerance_source` says
// where the tolerance comes from ("[mechanics] force_tolerance").
std::string unresolvableForces(double force_scale, const std::string& scale_formula, double tolerance,
                               const std::string& tolerance_source);

}  // namespace cortex
