#pragma once
// Test support: the mission's chief and relative orbits (Guffanti et al., AAS 23-149, 2023,
// Table 5; docs/conventions.md).

#include <cmath>
#include <numbers>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/constants.hpp"

namespace visors::control::test {

/// Chief (DSC) mean elements at t0: a = R_E + 500 km, e = 0.004, i = 97.8 deg, RAAN 157.5 deg,
/// argp 90 deg, M 0.
inline astro::KeplerianElements mission_chief() {
  constexpr double deg = std::numbers::pi / 180.0;
  return {6378136.3 + 500e3, 0.004, 97.8 * deg, 157.5 * deg, 90.0 * deg, 0.0};
}

/// Keplerian period of the mission chief [s].
inline double period_s() {
  const double a = mission_chief().a;
  return 2.0 * std::numbers::pi * std::sqrt(a * a * a / core::EarthGravityConstants{}.mu);
}

/// Dimensionless ROE of the mission chief from a*dROE [m].
inline astro::RelativeOrbitalElements roe_m(double da, double dl, double dex, double dey, double dix, double diy) {
  astro::RelativeOrbitalElements r;
  r << da, dl, dex, dey, dix, diy;
  return r / mission_chief().a;
}

/// The paper's science orbit and the standby orbit, a*dROE in metres.
inline astro::RelativeOrbitalElements science() { return roe_m(-2.62, 45.21, -34.51, 4.78, -18.72, 2.72); }
inline astro::RelativeOrbitalElements standby() { return roe_m(0, 0, 0, 200, 0, 200); }

}  // namespace visors::control::test
