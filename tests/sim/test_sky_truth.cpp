// The truth's sky (sim/sky_truth.hpp): the interpolated ephemeris against ERFA's series itself,
// and the truth's apparent Sun and target against the flight software's independent code.
#include <gtest/gtest.h>

#include <erfa.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "visors/astro/apparent_sun.hpp"
#include "visors/sim/sky_truth.hpp"

namespace {

using visors::core::GpsTime;
using visors::core::TimeScale;
constexpr double kAuM = 149597870700.0;
constexpr double kRadToArcsec = 180.0 / M_PI * 3600.0;

double angle_arcsec(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * kRadToArcsec;
}

TEST(SkyTruth, InterpolatedEphemerisMatchesTheSeries) {
  // Cubic Hermite on a 60 s grid: the truncation bound h^4 max|x''''| / 384 is ~1e-11 m for the
  // annual and monthly motions, but the series' velocity is a series of its own, not exactly the
  // derivative of its position, and the interpolant inherits the difference: measured 6.6 mm and
  // 0.16 mm/s (2026-11). Bounds 1 cm and 1 mm/s: 7e-14 rad of direction at 1 au, 3e-12 rad of
  // aberration. Random instants, backwards and forwards (the cache's slots are reused).
  visors::sim::SkyTruth sky;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> s(0.0, 20.0 * 86400.0);
  const GpsTime t0 = *GpsTime::from_calendar({2024, 10, 1, 0, 0, 0, 0}, TimeScale::kGps);
  double worst_r = 0.0, worst_v = 0.0;
  for (int k = 0; k < 500; ++k) {
    const GpsTime t = t0 + s(rng);
    const auto e = sky.earth(t);
    const auto jd = t.jd_tt();
    double pvh[2][3], pvb[2][3];
    eraEpv00(jd.jd1, jd.jd2, pvh, pvb);
    for (int i = 0; i < 3; ++i) {
      worst_r = std::max({worst_r, std::abs(e.barycentric_pv[0][i] - pvb[0][i]) * kAuM, std::abs(e.heliocentric_p[i] - pvh[0][i]) * kAuM});
      worst_v = std::max({worst_v, std::abs(e.barycentric_pv[1][i] - pvb[1][i]) * kAuM / 86400.0,
                          std::abs(e.heliocentric_v[i] - pvh[1][i]) * kAuM / 86400.0});
    }
  }
  EXPECT_LT(worst_r, 1e-2);  // [m]
  EXPECT_LT(worst_v, 1e-3);  // [m/s]
}

TEST(SkyTruth, ApparentSunAgreesWithTheFlightCode) {
  // Two implementations (ERFA's astrometry vs astro/apparent_sun.cpp) of the same definition
  // over one day of a 500 km orbit: the required bound is 0.5"; they agree far better.
  visors::sim::SkyTruth sky;
  const GpsTime t0 = *GpsTime::from_calendar({2024, 10, 1, 0, 0, 0, 0}, TimeScale::kGps);
  const double n = std::sqrt(3.986004418e14 / std::pow(6878136.3, 3));
  double worst = 0.0;
  for (double ts = 0.0; ts < 86400.0; ts += 97.0) {
    const double u = n * ts;
    const visors::core::StateVector x{6878136.3 * Eigen::Vector3d(std::cos(u), 0.2 * std::sin(u), 0.98 * std::sin(u)),
                                      7612.6 * Eigen::Vector3d(-std::sin(u), 0.2 * std::cos(u), 0.98 * std::cos(u))};
    const GpsTime t = t0 + ts;
    worst = std::max(worst, angle_arcsec(sky.sun(t, x).apparent_unit_gcrf, visors::astro::sun_view(t, x).apparent_unit_gcrf));
  }
  EXPECT_LT(worst, 1e-3);  // [arcsec]
}

TEST(SkyTruth, TargetIsTheCommandedOffsetFromTheApparentSun) {
  // A target 300" east and 200" south of the disc centre: sqrt(300^2 + 200^2) = 360.6" from the
  // apparent Sun (gnomonic: tan(angle) = |offset|), and where the flight code puts it.
  const Eigen::Vector2d offset = Eigen::Vector2d(300.0, -200.0) / kRadToArcsec;
  visors::sim::SkyTruth sky(offset);
  const GpsTime t = *GpsTime::from_calendar({2024, 10, 1, 6, 0, 0, 0}, TimeScale::kGps);
  const visors::core::StateVector x{{6878136.3, 0.0, 0.0}, {0.0, 1045.0, 7540.0}};
  const Eigen::Vector3d target = sky.target_unit_gcrf(t, x);
  EXPECT_NEAR(angle_arcsec(target, sky.sun(t, x).apparent_unit_gcrf), std::atan(offset.norm()) * kRadToArcsec, 1e-6);
  EXPECT_LT(angle_arcsec(target, visors::astro::apparent_target_unit_gcrf(t, x, offset)), 1e-3);
}

}  // namespace
