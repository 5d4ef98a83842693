#pragma once
// The GPS broadcast (Klobuchar) ionospheric model for single-frequency L1 users, IS-GPS-200
// (Rev. N) 20.3.3.5.2.5 and Figure 20-4: a cosine of local time at the ionospheric pierce point
// (350 km shell) with amplitude and period given by the broadcast alpha/beta polynomials in
// geomagnetic latitude, and the obliquity factor F = 1 + 16 (0.53 - E)^3. The result is the
// GROUND model: the delay of a receiver below the whole ionosphere. Pseudorange is delayed by it,
// carrier phase advanced by the same amount (first order, dispersive medium).
//
// Angles in the document are semicircles; this interface takes radians and converts once.

#include <array>

#include "core/gps_time.hpp"
#include "core/status.hpp"

namespace visors::gnss {

struct KlobucharCoefficients {
  std::array<double, 4> alpha{};  // [s, s/semicircle, s/semicircle^2, s/semicircle^3]
  std::array<double, 4> beta{};   // [s, s/semicircle, s/semicircle^2, s/semicircle^3]
};

/// The user position and the satellite direction.
struct KlobucharGeometry {
  double latitude = 0.0;   // geodetic [rad], [-pi/2, pi/2]
  double longitude = 0.0;  // [rad]
  double azimuth = 0.0;    // of the satellite, from north towards east [rad]
  double elevation = 0.0;  // of the satellite [rad], [0, pi/2]
};

/// Vertical-to-slant delay on L1 [s] at GPS time t. Errors name the field: non-finite values,
/// latitude outside [-pi/2, pi/2], elevation outside [0, pi/2].
core::Result<double> klobuchar_delay_s(const KlobucharCoefficients& coefficients, const KlobucharGeometry& geometry,
                                       core::GpsTime t);

/// The same in metres (times the speed of light).
core::Result<double> klobuchar_delay_m(const KlobucharCoefficients& coefficients, const KlobucharGeometry& geometry,
                                       core::GpsTime t);

}  // namespace visors::gnss
