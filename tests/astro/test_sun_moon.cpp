// Low-precision Sun and Moon (M&G sec. 3.3.2): regression against an independent implementation
// of the same series, and accuracy against ERFA's much better ephemerides.
#include <gtest/gtest.h>

// ERFA is a private dependency of visors_core; its header is in the system include path and the
// library comes with visors_core's link interface.
#include <erfa.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include <Eigen/Geometry>

#include "visors/astro/sun_moon.hpp"
#include "visors/core/gps_time.hpp"

namespace {

using visors::core::GpsTime;
using visors::core::TimeScale;

constexpr double kAu = 149597870700.0;  // [m], IAU 2012 (ERFA_DAU)
constexpr double kRadToDeg = 180.0 / M_PI;

// The instant whose TT is MJD `mjd_tt` (TT = GPST + 51.184 s, so TT = MJD 44244.0 at
// 1980-01-05T23:59:08.816 GPST).
GpsTime from_mjd_tt(double mjd_tt) {
  const GpsTime epoch_tt = *GpsTime::parse("1980-01-05T23:59:08.816", TimeScale::kGps);
  return epoch_tt + (mjd_tt - 44244.0) * 86400.0;
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * kRadToDeg;
}

TEST(SunMoon, RegressionAgainstBraheAtMjdTt60310p25) {
  // brahe (duncaneddy/brahe) src/orbit_dynamics/ephemerides.rs tests, MJD_TT 60310.25: the same
  // M&G series (revolution form) implemented independently; agreement to 1 m checks the
  // transcription of every term, not the physics.
  const GpsTime t = from_mjd_tt(60310.25);
  EXPECT_EQ(t.jd_tt().jd2, 0.25);
  const Eigen::Vector3d sun = visors::astro::sun_position_gcrf(t);
  // loose: measured 3.4e-3 / 5.5e-4 / 2.7e-4 m (Sun), 5e-6 .. 1.6e-5 m (Moon) (2026-11), bound 1 m
  EXPECT_NEAR(sun.x(), 25266917244.8224, 1.0);
  EXPECT_NEAR(sun.y(), -132958014059.854, 1.0);
  EXPECT_NEAR(sun.z(), -57644353905.9469, 1.0);
  const Eigen::Vector3d moon = visors::astro::moon_position_gcrf(t);
  EXPECT_NEAR(moon.x(), -376313966.331919, 1.0);
  EXPECT_NEAR(moon.y(), 125552784.254334, 1.0);
  EXPECT_NEAR(moon.z(), 80458346.9703463, 1.0);
}

TEST(SunMoon, AccuracyAgainstErfaEphemerides2020To2030) {
  // ERFA eraEpv00 (VSOP2000-based, ~km): geocentric Sun = -(heliocentric Earth); eraMoon98
  // (Meeus/ELP, ~arcsec): geocentric Moon. Both GCRS-aligned, TT used for TDB (< 2 ms).
  // 1000 epochs, 2020-01-01 .. 2030-01-01, step ~3.65 d + a drifting time of day.
  double sun_dir = 0.0;
  double sun_dist = 0.0;
  double moon_dir = 0.0;
  double moon_dist = 0.0;
  for (int k = 0; k < 1000; ++k) {
    const double mjd_tt = 58849.0 + 3.6525 * k + 0.137 * k;
    const GpsTime t = from_mjd_tt(mjd_tt);
    const auto tt = t.jd_tt();
    double pvh[2][3];
    double pvb[2][3];
    (void)eraEpv00(tt.jd1, tt.jd2, pvh, pvb);
    const Eigen::Vector3d sun_ref = -kAu * Eigen::Vector3d(pvh[0][0], pvh[0][1], pvh[0][2]);
    double pv[2][3];
    eraMoon98(tt.jd1, tt.jd2, pv);
    const Eigen::Vector3d moon_ref = kAu * Eigen::Vector3d(pv[0][0], pv[0][1], pv[0][2]);

    const Eigen::Vector3d sun = visors::astro::sun_position_gcrf(t);
    const Eigen::Vector3d moon = visors::astro::moon_position_gcrf(t);
    sun_dir = std::max(sun_dir, angle_deg(sun, sun_ref));
    sun_dist = std::max(sun_dist, std::abs(sun.norm() / sun_ref.norm() - 1.0));
    moon_dir = std::max(moon_dir, angle_deg(moon, moon_ref));
    moon_dist = std::max(moon_dist, std::abs(moon.norm() / moon_ref.norm() - 1.0));
  }
  std::cout << "[ measured ] Sun: direction " << sun_dir << " deg, distance " << sun_dist
            << "; Moon: direction " << moon_dir << " deg, distance " << moon_dist << "\n";
  // measured regression bounds: Sun 0.100 deg, 8.1e-5; Moon 0.0805 deg, 1.3e-3 (2026-11); bounds 0.11 deg, 1e-4, 0.09 deg, 2e-3
  EXPECT_LT(sun_dir, 0.11);
  EXPECT_LT(sun_dist, 1e-4);
  EXPECT_LT(moon_dir, 0.09);
  EXPECT_LT(moon_dist, 2e-3);
}

TEST(SunMoon, MagnitudesAreSane) {
  const GpsTime t = *GpsTime::parse("2024-10-01T00:00:00", TimeScale::kGps);
  // Earth orbit eccentricity 0.0167 (|r| within 1 +- 0.017 AU); measured 1.2e-3 (2026-11)
  EXPECT_NEAR(visors::astro::sun_position_gcrf(t).norm() / kAu, 1.0, 0.02);
  const double moon = visors::astro::moon_position_gcrf(t).norm();
  // published extremes of the Moon's geocentric distance (~356 400 .. 406 700 km); measured 4.05e8 m (2026-11)
  EXPECT_GT(moon, 356e6);
  EXPECT_LT(moon, 407e6);
}

}  // namespace
