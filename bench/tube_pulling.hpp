// The tube-pulling scenario shared by the tube test (tests/interact/test_membrane_tube.cpp)
// and the protrusion-threshold bench: a square patch at z = 200 nm under tension over a
// bundle of rigid filaments (each one clamped cylinder: actin's hinges buckle under the
// loads of a tube once the filaments are a few hundred nanometres long, and the bundle
// slips off it), 10 nm apart, tips 40 nm under the patch, in a 1 µm cube of G-actin held
// at `concentration` by exchange with a reservoir (c = k_in / 10 s⁻¹).
#pragma once

#include <string>

namespace cortex::bench {

struct TubePulling {
  unsigned seed = 1;
  double end_time = 1.0, window = 0.01;  // s
  double patch = 1000.0;                 // nm, edge of the square patch
  double tension = 0.02;                 // pN/nm (κ = 100 pN·nm)
  int filaments = 4;
  double concentration = 6.0;            // µM
  double on = 116.0, off = 5.8;          // plus-end rates, 1/(µM·s) and 1/s
};

inline std::string tubePullingConfig(const TubePulling& s) {
  const auto num = [](double x) { return std::to_string(x); };
  return "[simulation]\nseed = " + std::to_string(s.seed) + "\nend_time = " + num(s.end_time) +
         "\nchemistry_window = " + num(s.window) + R"(
snapshot_interval = 100.0

[compartments]
size = 250.0
shape = [4, 4, 4]

[[species]]
name = "G"
diffusion = 2.0e7
concentration = )" + num(s.concentration) +
         "\n\n[[reaction]]\nequation = \"-> G\"\nrate = " + num(10.0 * s.concentration) + R"(
[[reaction]]
equation = "G ->"
rate = 10.0

[[membrane]]
name = "patch"
shape = "plane"
center = [500.0, 500.0, 200.0]
size = [)" + num(s.patch) + ", " + num(s.patch) + R"(]
mesh_size = 25.0
boundary = "fixed"
bending_modulus = 100.0
tension = )" + num(s.tension) + R"(
area_model = "none"
remesh = true

[[filament_type]]
name = "actin"
monomer_species = "G"
cylinder_monomers = 400
plus_on = )" + num(s.on) + "\nplus_off = " + num(s.off) + R"(
minus_on = 0.0
minus_off = 0.0

[[filaments]]
count = )" + std::to_string(s.filaments) + R"(
length = 108.0
placement = "bundle"
center = [500.0, 500.0, 106.0]
direction = [0.0, 0.0, 1.0]
spacing = 10.0
clamped_minus_end = true
)";
}

}  // namespace cortex::bench
