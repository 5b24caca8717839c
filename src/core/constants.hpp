// Physical constants in cortex units (nm, s, pN, pN·nm, K).
#pragma once

namespace cortex::constants {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kBoltzmann = 1.380649e-2;  // pN·nm/K
inline constexpr double kDefaultTemperature = 298.15;  // K
// Largest |coordinate| of a membrane, generated or loaded (nm): beyond a metre a double
// keeps too few digits for a mesh of nanometres.
inline constexpr double kMaxCoordinate = 1e9;

}  // namespace cortex::constants
