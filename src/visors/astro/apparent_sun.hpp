#pragma once
// The apparent direction of the Sun, and of an observation target on the solar disc, as seen from
// a spacecraft: what the telescope's line of sight must be aligned with (docs/apparent-sun.md).
//
// Model (Kaplan et al. 1989, "Mean and apparent place computations in the new IAU system. III",
// AJ 97, 1197; Urban & Seidelmann, Explanatory Supplement to the Astronomical Almanac, 3rd ed.,
// ch. 7):
//   1. Ephemeris: the Earth's barycentric and heliocentric position and velocity from ERFA eraEpv00
//      (VSOP2000-based series, 4.6 km / 0.006" worst case against DE405 over 1900-2100, its
//      documented accuracy); the Sun's barycentric state = Earth's barycentric - heliocentric.
//      Argument TT for TDB (|TDB - TT| < 1.7 ms: 0.00007" of solar motion).
//   2. Light time: the Sun where it was when the light left it, t - tau with
//      tau = |s_B(t - tau) - o_B(t)| / c (two fixed-point steps; the Sun's barycentric motion,
//      ~13 m/s, over tau ~ 499 s moves it 0.009": linear in its barycentric velocity).
//   3. Aberration: special-relativistic, with the observer's barycentric velocity (Earth's ~30 km/s:
//      20.5" annual, plus the orbital 7.6 km/s: up to 5.2"): with beta = v_B / c and
//      g = sqrt(1 - beta^2), p' is proportional to g p + (1 + (p.beta) / (1 + g)) beta.
//      The Sun's gravitational deflection of its own light is zero; the Earth's is at most
//      4 GM / (c^2 R) = 0.0006" (a ray grazing the limb) and is ignored.
// Output axes: GCRF (the GCRS, ICRS-aligned). The apparent direction differs from the geometric
// one by ~20" (4 mm at the 40 m focal distance); the low-precision series of astro/sun_moon.hpp is
// ~300" off (57 mm): it is kept only for forces and shadows, where that is harmless.
//
// The target: a direction on the sky given by its standard (gnomonic tangent-plane) coordinates
// about the apparent Sun centre, xi towards the east (increasing right ascension) and eta towards
// the north celestial pole, both [rad]: target ~ s + xi e + eta n, with e = unit(z x s),
// n = s x e, z the GCRF pole. (0, 0) is the Sun's centre; the solar disc's radius is ~960".
//
// Flight code: allocation-free and exception-free; eraEpv00 costs ~10-20 us per call.

#include <Eigen/Core>

#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"

namespace visors::astro {

struct SunView {
  Eigen::Vector3d apparent_unit_gcrf = Eigen::Vector3d::UnitX();   // light time and aberration [-]
  Eigen::Vector3d geometric_unit_gcrf = Eigen::Vector3d::UnitX();  // Sun centre at t, no correction [-]
  double distance_m = 0.0;  // geometric distance from the observer to the Sun's centre at t [m]
};

/// The Sun's centre seen at `t` by an observer with geocentric GCRF state `observer_gcrf`
/// ([m], [m/s]). Preconditions (debug-checked): finite state, |v| < c.
[[nodiscard]] SunView sun_view(core::GpsTime t, const core::StateVector& observer_gcrf);

/// The unit direction with standard coordinates `offset_rad` = (xi east, eta north) [rad] about
/// `centre_unit_gcrf` (a unit vector not along the GCRF pole).
[[nodiscard]] Eigen::Vector3d offset_on_sky(const Eigen::Vector3d& centre_unit_gcrf, const Eigen::Vector2d& offset_rad);

/// The apparent direction of the target at `offset_rad` on the solar disc from the observer:
/// offset_on_sky(sun_view(t, observer).apparent_unit_gcrf, offset_rad).
[[nodiscard]] Eigen::Vector3d apparent_target_unit_gcrf(core::GpsTime t, const core::StateVector& observer_gcrf,
                                                        const Eigen::Vector2d& offset_rad);

}  // namespace visors::astro
