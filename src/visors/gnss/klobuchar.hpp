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

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"

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

/// The part of the ionosphere above a low-Earth-orbit receiver
/// (docs/algorithms/gnss-measurements.md#ionosphere-above-a-leo-receiver; Montenbruck & Gill 2005
/// sec. 6.4.2 for the thin-shell mapping). The ground model
/// describes the whole electron column; a receiver at 500 km sees only its topside. Scaling used:
///   vertical = topside_fraction x (the ground model's delay at the receiver's zenith, i.e. with
///              the obliquity factor F(90 deg) removed; the zenith pierce point is the receiver's
///              own latitude and longitude to 1e-3 semicircle);
///   slant    = vertical x M(E), M(E) = 1 / sqrt(1 - ((R + h) cos E / (R + h_shell))^2), a thin
///              shell at shell_height_m above the Earth (R = 6371 km), E the geodetic elevation
///              of the satellite at the receiver, taken as 0 for rays below the local horizontal
///              (they are dropped by the occultation test well before the mapping matters).
/// topside_fraction 0.35 and a 1000 km shell are this project's choice, of the order of published
/// LEO scale factors (0.25 on average at ~480 km in 2004 from the IRI model, Kim & Kim 2014,
/// Korean J. Remote Sens. 30(2):331-339; a modified Klobuchar model with a raised shell for
/// GRACE: Yang, Li & Zhang 2014, J. Earth Syst. Sci. 123(4):767-778); at 40 m baselines the single
/// difference of this delay is far below 1 mm either way.
/// Continuity: the ground model switches to the night-time constant at |x| = 1.57 (x the phase of
/// its cosine of local time), where its cosine polynomial 1 - x^2/2 + x^4/24 is still 0.0207: a
/// jump of 0.0207 x amplitude. A receiver in low Earth orbit crosses that line within seconds
/// twice an orbit, and the jump (up to 9 cm slant with the 2024 NYA1 coefficients at 500 km) would
/// be a discontinuity of the simulated carrier phase. This model keeps the day-time term until the
/// polynomial's root, |x| = sqrt(6 - 2 sqrt 3) = 1.5925, so the delay is continuous (with a kink
/// there, like the model's other clamps); it equals the scaled ground model wherever |x| < 1.57 or
/// |x| >= 1.5925, and differs by less than 0.0207 x amplitude (scaled) in between.
struct TopsideIonosphere {
  double topside_fraction = 0.35;   // share of the vertical column above the receiver, [0, 1]
  double shell_height_m = 1000e3;   // thin-shell height above the Earth's mean radius [m]
};

/// L1 slant delay [m] for a receiver at `altitude_m` (geometry: receiver latitude/longitude and
/// the satellite's azimuth/elevation, elevation in [-pi/2, pi/2]). Errors name the field:
/// "topside_fraction" outside [0, 1], "shell_height_m" not above the receiver, and the ground
/// model's own checks.
core::Result<double> klobuchar_topside_delay_m(const KlobucharCoefficients& coefficients, const KlobucharGeometry& geometry,
                                               double altitude_m, core::GpsTime t,
                                               const TopsideIonosphere& topside = {});

}  // namespace visors::gnss
