#pragma once
// Low-precision analytical Sun and Moon positions, Montenbruck & Gill, Satellite Orbits (2000),
// sec. 3.3.2, with the mean arguments in revolutions as in the authors' reference code (from
// Montenbruck & Pfleger's MiniSun/MiniMoon). The textbook prints the same arguments in degrees
// with different roundings (e.g. Moon F0 = 93.27283 deg vs 0.259086 rev = 93.27096 deg); the two
// forms differ by ~17 km for the Sun and ~2 km for the Moon, far below the series' accuracy.
//
// Input time scale: TT (T = Julian centuries of TT since J2000). Output: geocentric position in
// the mean equator and equinox of J2000 (EME2000), used as GCRF: the ~23 mas frame bias is
// ignored (0.8 m at lunar distance, 17 km at 1 AU, both far below the model error).
//
// Accuracy against ERFA eraEpv00 (Sun) and eraMoon98 (Moon), 1000 epochs over 2020-2030
// (tests/astro/test_sun_moon.cpp; measured maximum, then the tested bound):
//   Sun direction 0.100 deg = 6.0' (0.11 deg), distance 8.1e-5 = 12 000 km (1e-4);
//   Moon direction 0.081 deg = 4.8' (0.09 deg), distance 0.13 % = 500 km (0.2 %).
// The Sun error grows with time (fixed perigee longitude: ~0.3 deg/century of perihelion motion).
// Good enough for third-body accelerations, SRP direction, eclipses (a 6' Sun error moves a
// shadow entry by ~1.6 s) and the Sun-pointing geometry at the 0.1 deg level.

#include <Eigen/Core>

#include "visors/core/gps_time.hpp"

namespace visors::astro {

/// Geocentric Sun position, EME2000 ~ GCRF [m].
Eigen::Vector3d sun_position_gcrf(core::GpsTime t);

/// Geocentric Moon position, EME2000 ~ GCRF [m].
Eigen::Vector3d moon_position_gcrf(core::GpsTime t);

}  // namespace visors::astro
