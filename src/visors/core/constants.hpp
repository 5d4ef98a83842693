#pragma once
// Physical constants shared by every layer. Model parameters that a user may change (Earth
// gravity constants of a given field, spacecraft properties) are NOT here: they live in
// configuration structures with these values as documented defaults.

#include <numbers>

namespace visors::core {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kDegToRad = std::numbers::pi / 180.0;
inline constexpr double kArcsecToRad = std::numbers::pi / 648000.0;

inline constexpr double kSpeedOfLight = 299792458.0;  // [m/s], exact (SI)

/// Nominal mean angular velocity of the Earth, IERS Conventions 2010 Table 1.1 [rad/s].
inline constexpr double kEarthRotationRate = 7.292115146706979e-5;
inline constexpr double kSecondsPerDay = 86400.0;

/// Earth gravity constants of the GRACE fields (GGM01S/GGM05S/JGM-3 `.gfc` headers) and the
/// J2 the project's analytical models use by default: EGM96's, -sqrt(5) C̄20 with
/// C̄20 = -0.484165371736e-3 (Lemoine et al. 1998, NASA/TP-1998-206861), rounded to 9 digits
/// (docs/algorithms/dynamics.md#potential-and-normalisation).
struct EarthGravityConstants {
  double mu = 3.986004415e14;  // [m^3/s^2]
  double re = 6378136.3;       // [m]
  double j2 = 1.08262668e-3;   // [-]
};

inline constexpr double kWgs84SemiMajorAxis = 6378137.0;              // [m]
inline constexpr double kWgs84Flattening = 1.0 / 298.257223563;       // [-]

}  // namespace visors::core
