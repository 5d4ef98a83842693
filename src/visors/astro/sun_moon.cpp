#include "visors/astro/sun_moon.hpp"

#include <cmath>

#include "visors/core/constants.hpp"

namespace visors::astro {
namespace {

using core::kArcsecToRad;
using core::kTwoPi;

// Obliquity of the J2000 ecliptic used by M&G sec. 3.3.2 [rad].
constexpr double kObliquityJ2000 = 23.43929111 * core::kDegToRad;

// An angle given in revolutions -> [rad] in [0, 2 pi), reducing before scaling to keep precision.
double revolutions(double rev) { return kTwoPi * (rev - std::floor(rev)); }

// Julian centuries of TT since J2000.0 (JD 2451545.0 TT).
double centuries_tt(core::GpsTime t) {
  const core::JulianDate tt = t.jd_tt();
  return ((tt.jd1 - 2451545.0) + tt.jd2) / 36525.0;
}

// Ecliptic (J2000) -> equatorial (EME2000): rotation about x by -epsilon.
Eigen::Vector3d ecliptic_to_equatorial(const Eigen::Vector3d& p) {
  const double c = std::cos(kObliquityJ2000);
  const double s = std::sin(kObliquityJ2000);
  return {p.x(), c * p.y() - s * p.z(), s * p.y() + c * p.z()};
}

}  // namespace

Eigen::Vector3d sun_position_gcrf(core::GpsTime t) {
  const double tc = centuries_tt(t);
  // Mean anomaly of the Sun; ecliptic longitude = perigee longitude (282.9400 deg = 0.7859444
  // rev) + M + equation of centre (6892" sin M + 72" sin 2M); distance from the Kepler expansion.
  const double m = revolutions(0.9931267 + 99.9973583 * tc);
  const double lambda = revolutions(0.7859444 + m / kTwoPi +
                                    (6892.0 * std::sin(m) + 72.0 * std::sin(2.0 * m)) / 1296.0e3);
  const double r = 149.619e9 - 2.499e9 * std::cos(m) - 0.021e9 * std::cos(2.0 * m);  // [m]
  return ecliptic_to_equatorial({r * std::cos(lambda), r * std::sin(lambda), 0.0});
}

Eigen::Vector3d moon_position_gcrf(core::GpsTime t) {
  const double tc = centuries_tt(t);
  // Mean arguments: mean longitude (referred to the J2000 equinox: the precession rate 1.3972
  // deg/cy is already removed), Moon's and Sun's mean anomalies, argument of latitude F,
  // elongation D.
  const double l0 = revolutions(0.606433 + 1336.851344 * tc);
  const double l = revolutions(0.374897 + 1325.552410 * tc);
  const double lp = revolutions(0.993133 + 99.997361 * tc);
  const double f = revolutions(0.259086 + 1342.227825 * tc);
  const double d = revolutions(0.827361 + 1236.853086 * tc);

  // Perturbations in longitude ["].
  const double dlambda = 22640.0 * std::sin(l) + 769.0 * std::sin(2.0 * l) -
                         4586.0 * std::sin(l - 2.0 * d) + 2370.0 * std::sin(2.0 * d) -
                         668.0 * std::sin(lp) - 412.0 * std::sin(2.0 * f) -
                         212.0 * std::sin(2.0 * l - 2.0 * d) - 206.0 * std::sin(l + lp - 2.0 * d) +
                         192.0 * std::sin(l + 2.0 * d) - 165.0 * std::sin(lp - 2.0 * d) +
                         148.0 * std::sin(l - lp) - 125.0 * std::sin(d) -
                         110.0 * std::sin(l + lp) - 55.0 * std::sin(2.0 * f - 2.0 * d);
  const double lambda = l0 + dlambda * kArcsecToRad;

  // Latitude ["]: main term with the argument F + (lambda - L0) + 412" sin 2F + 541" sin l'.
  const double u = f + (dlambda + 412.0 * std::sin(2.0 * f) + 541.0 * std::sin(lp)) * kArcsecToRad;
  const double h = f - 2.0 * d;
  const double beta =
      (18520.0 * std::sin(u) - 526.0 * std::sin(h) + 44.0 * std::sin(l + h) -
       31.0 * std::sin(-l + h) - 25.0 * std::sin(-2.0 * l + f) - 23.0 * std::sin(lp + h) +
       21.0 * std::sin(-l + f) + 11.0 * std::sin(-lp + h)) *
      kArcsecToRad;

  // Distance [km] -> [m].
  const double r = 1e3 * (385000.0 - 20905.0 * std::cos(l) - 3699.0 * std::cos(2.0 * d - l) -
                          2956.0 * std::cos(2.0 * d) - 570.0 * std::cos(2.0 * l) +
                          246.0 * std::cos(2.0 * l - 2.0 * d) - 205.0 * std::cos(lp - 2.0 * d) -
                          171.0 * std::cos(l + 2.0 * d) - 152.0 * std::cos(l + lp - 2.0 * d));

  const double cb = std::cos(beta);
  return ecliptic_to_equatorial(
      {r * std::cos(lambda) * cb, r * std::sin(lambda) * cb, r * std::sin(beta)});
}

}  // namespace visors::astro
