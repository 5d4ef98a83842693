// The apparent Sun of the flight software (astro/apparent_sun.hpp): published apparent places,
// ERFA's astrometry chain as an independent computation, and the sizes and signs of aberration.
#include <gtest/gtest.h>

#include <erfa.h>
#include <erfam.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "visors/astro/apparent_sun.hpp"
#include "visors/astro/sun_moon.hpp"
#include "visors/core/gps_time.hpp"

namespace {

using visors::core::GpsTime;
using visors::core::StateVector;
using visors::core::TimeScale;

constexpr double kRadToArcsec = 180.0 / M_PI * 3600.0;
constexpr double kArcsecToRad = 1.0 / kRadToArcsec;

// The instant whose TT is the given calendar date at 0h (TT = GPST + 51.184 s).
GpsTime at_0h_tt(int year, int month, int day) {
  return *GpsTime::from_calendar({year, month, day, 0, 0, 0, 0}, TimeScale::kGps) - 51.184;
}

double angle_arcsec(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * kRadToArcsec;
}

// Geocentric apparent right ascension [h] and declination [deg] referred to the true equator and
// equinox of date: the GCRS direction rotated by ERFA's bias-precession-nutation matrix
// (IAU 2006/2000A).
Eigen::Vector2d ra_dec_of_date(GpsTime t, const Eigen::Vector3d& unit_gcrf) {
  double rnpb[3][3];
  const auto jd = t.jd_tt();
  eraPnm06a(jd.jd1, jd.jd2, rnpb);
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = rnpb[i][j];
  const Eigen::Vector3d v = m * unit_gcrf;
  double ra = std::atan2(v.y(), v.x());
  if (ra < 0.0) ra += 2.0 * M_PI;
  return {ra * 12.0 / M_PI, std::asin(v.z()) * 180.0 / M_PI};
}

// Geocentric observer: the Earth's centre (its barycentric velocity is added inside).
const StateVector kGeocentre{};

TEST(ApparentSun, AstronomicalAlmanac1982May1RightAscension) {
  // The Astronomical Almanac for 1982, apparent Sun at 1982 May 1, 0h dynamical time:
  // 02h31m32.58s +14d54'34.9" (quoted in the IDL Astronomy Library's sunpos documentation).
  // Tolerance 0.5" (the required bound; the printed precision is 0.15" in RA, 0.1" in Dec).
  const GpsTime t = at_0h_tt(1982, 5, 1);
  const Eigen::Vector2d rd = ra_dec_of_date(t, visors::astro::sun_view(t, kGeocentre).apparent_unit_gcrf);
  const double ra_ref_h = 2.0 + 31.0 / 60.0 + 32.58 / 3600.0;
  EXPECT_NEAR((rd[0] - ra_ref_h) * 15.0 * 3600.0 * std::cos(rd[1] * M_PI / 180.0), 0.0, 0.5);
}

TEST(ApparentSun, AstronomicalAlmanac1982May1Declination) {
  const GpsTime t = at_0h_tt(1982, 5, 1);
  const Eigen::Vector2d rd = ra_dec_of_date(t, visors::astro::sun_view(t, kGeocentre).apparent_unit_gcrf);
  const double dec_ref_deg = 14.0 + 54.0 / 60.0 + 34.9 / 3600.0;
  EXPECT_NEAR((rd[1] - dec_ref_deg) * 3600.0, 0.0, 0.5);
}

TEST(ApparentSun, Meeus1992Oct13RightAscension) {
  // Meeus, Astronomical Algorithms (2nd ed., 1998), Example 25.b, 1992 Oct 13.0 TD, the full
  // VSOP87 method, as reproduced by the arqastwb R package (tests/testthat/test_sun.R):
  // alpha = 13.22521186891 h, delta = -7.783870593711 deg. Tolerance 0.5".
  const GpsTime t = at_0h_tt(1992, 10, 13);
  const Eigen::Vector2d rd = ra_dec_of_date(t, visors::astro::sun_view(t, kGeocentre).apparent_unit_gcrf);
  EXPECT_NEAR((rd[0] - 13.22521186891) * 15.0 * 3600.0 * std::cos(rd[1] * M_PI / 180.0), 0.0, 0.5);
}

TEST(ApparentSun, Meeus1992Oct13Declination) {
  const GpsTime t = at_0h_tt(1992, 10, 13);
  const Eigen::Vector2d rd = ra_dec_of_date(t, visors::astro::sun_view(t, kGeocentre).apparent_unit_gcrf);
  EXPECT_NEAR((rd[1] - (-7.783870593711)) * 3600.0, 0.0, 0.5);
}

// A random low-Earth-orbit state: |r| 6878 km, circular speed, random directions.
StateVector random_leo(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  const Eigen::Vector3d r = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized() * 6878136.3;
  Eigen::Vector3d along = Eigen::Vector3d(n(rng), n(rng), n(rng)).cross(r).normalized();
  return {r, along * 7612.6};
}

// ERFA's astrometry chain, one evaluation per instant (no interpolation): eraEpv00 at t and at
// the emission time, eraApcs for the observer's barycentric state, eraAb for aberration.
Eigen::Vector3d erfa_apparent_sun(GpsTime t, const StateVector& x) {
  const auto jd = t.jd_tt();
  double pvh[2][3], pvb[2][3];
  eraEpv00(jd.jd1, jd.jd2, pvh, pvb);
  double pv[2][3];
  for (int i = 0; i < 3; ++i) {
    pv[0][i] = x.r[i];
    pv[1][i] = x.v[i];
  }
  eraASTROM astrom;
  eraApcs(jd.jd1, jd.jd2, pv, pvb, pvh[0], &astrom);
  Eigen::Vector3d p(-astrom.eh[0], -astrom.eh[1], -astrom.eh[2]);
  double dist_au = astrom.em;
  for (int k = 0; k < 3; ++k) {
    const double tau_d = dist_au * ERFA_AULT / ERFA_DAYSEC;
    double h2[2][3], b2[2][3];
    eraEpv00(jd.jd1, jd.jd2 - tau_d, h2, b2);
    for (int i = 0; i < 3; ++i) p[i] = b2[0][i] - h2[0][i] - astrom.eb[i];
    dist_au = p.norm();
  }
  p.normalize();
  double pnat[3] = {p.x(), p.y(), p.z()}, ppr[3];
  eraAb(pnat, astrom.v, astrom.em, astrom.bm1, ppr);
  return Eigen::Vector3d(ppr[0], ppr[1], ppr[2]).normalized();
}

TEST(ApparentSun, AgreesWithErfaAstrometryFromLowEarthOrbit) {
  // 400 instants over 2024-2026, random 500 km orbit states. The flight code extrapolates the
  // Sun linearly over the light time and writes its own aberration; ERFA evaluates the
  // ephemeris at the emission time and adds the Sun's gravitational term (2e-12 rad).
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> days(0.0, 730.0);
  const GpsTime t0 = at_0h_tt(2024, 1, 1);
  double worst = 0.0;
  for (int k = 0; k < 400; ++k) {
    const GpsTime t = t0 + days(rng) * 86400.0;
    const StateVector x = random_leo(rng);
    worst = std::max(worst, angle_arcsec(visors::astro::sun_view(t, x).apparent_unit_gcrf, erfa_apparent_sun(t, x)));
  }
  EXPECT_LT(worst, 1e-3);  // [arcsec]; 0.2 um at 40 m
}

TEST(ApparentSun, AberrationIsAnnualPlusOrbitalInSize) {
  // |apparent - geometric| = |v_perp| / c to first order: Earth's 29.3-30.3 km/s gives
  // 20.1-20.9" (the constant of aberration 20.49552"), the orbital 7.6 km/s at most 5.2" more or
  // less.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> days(0.0, 365.0);
  for (int k = 0; k < 50; ++k) {
    const GpsTime t = at_0h_tt(2024, 1, 1) + days(rng) * 86400.0;
    const auto view = visors::astro::sun_view(t, random_leo(rng));
    const double a = angle_arcsec(view.apparent_unit_gcrf, view.geometric_unit_gcrf);
    EXPECT_GT(a, 20.1 - 5.3);
    EXPECT_LT(a, 20.9 + 5.3);
  }
}

TEST(ApparentSun, AberrationLeansTowardsTheObserversVelocity) {
  // Bradley's aberration: a moving observer sees the source displaced towards its velocity.
  // Two geocentric observers with opposite 7.6 km/s velocities normal to the Sun line: the
  // apparent directions differ by 2 v / c = 10.5" along that velocity.
  const GpsTime t = at_0h_tt(2024, 10, 1);
  const Eigen::Vector3d s = visors::astro::sun_view(t, kGeocentre).geometric_unit_gcrf;
  const Eigen::Vector3d w = s.cross(Eigen::Vector3d::UnitZ()).normalized();
  const auto plus = visors::astro::sun_view(t, {Eigen::Vector3d::Zero(), 7600.0 * w});
  const auto minus = visors::astro::sun_view(t, {Eigen::Vector3d::Zero(), -7600.0 * w});
  EXPECT_NEAR((plus.apparent_unit_gcrf - minus.apparent_unit_gcrf).dot(w) * kRadToArcsec, 2.0 * 7600.0 / 299792458.0 * kRadToArcsec, 0.01);
}

TEST(ApparentSun, DistanceIsTheGeometricSunObserverDistance) {
  // 2024-10-01: Earth-Sun distance 1.00133 au (ERFA eraEpv00 heliocentric Earth, same day); an
  // observer 6878 km sunward is that much closer.
  const GpsTime t = at_0h_tt(2024, 10, 1);
  const auto jd = t.jd_tt();
  double pvh[2][3], pvb[2][3];
  eraEpv00(jd.jd1, jd.jd2, pvh, pvb);
  const double d_au = std::sqrt(pvh[0][0] * pvh[0][0] + pvh[0][1] * pvh[0][1] + pvh[0][2] * pvh[0][2]);
  const auto geo = visors::astro::sun_view(t, kGeocentre);
  const auto sunward = visors::astro::sun_view(t, {geo.geometric_unit_gcrf * 6878136.3, Eigen::Vector3d::Zero()});
  EXPECT_NEAR(geo.distance_m, d_au * 149597870700.0, 1e-3);
  EXPECT_NEAR(geo.distance_m - sunward.distance_m, 6878136.3, 1.0);  // 1 m: the 0.01" parallax
}

TEST(ApparentSun, LowPrecisionSeriesIsMinutesOffOnTheMissionEpoch) {
  // Why the flight software and the truth no longer use astro/sun_moon.hpp for the line of sight:
  // on 2024-10-01 it is 296" from the geometric Sun (57 mm at 40 m).
  const GpsTime t = *GpsTime::from_calendar({2024, 10, 1, 0, 0, 0, 0}, TimeScale::kGps);
  const double a = angle_arcsec(visors::astro::sun_position_gcrf(t), visors::astro::sun_view(t, kGeocentre).geometric_unit_gcrf);
  EXPECT_GT(a, 250.0);
  EXPECT_LT(a, 350.0);
}

TEST(ApparentSun, OffsetOnSkyAgreesWithErfaTangentPlane) {
  // eraTpstv: the direction with standard coordinates (xi, eta) about a tangent point; xi east,
  // eta north, both ours and ERFA's. Offsets up to 1200" (past the solar limb).
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> off(-1200.0, 1200.0);
  double worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d c = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    const Eigen::Vector2d o(off(rng) * kArcsecToRad, off(rng) * kArcsecToRad);
    double v0[3] = {c.x(), c.y(), c.z()}, v[3];
    eraTpstv(o.x(), o.y(), v0, v);
    worst = std::max(worst, angle_arcsec(visors::astro::offset_on_sky(c, o), Eigen::Vector3d(v[0], v[1], v[2])));
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(ApparentSun, OffsetEastIncreasesRightAscension) {
  // Sign convention: xi > 0 moves the target east (larger right ascension), eta > 0 north.
  const Eigen::Vector3d c(1.0, 0.0, 0.0);  // RA 0, Dec 0
  const Eigen::Vector3d east = visors::astro::offset_on_sky(c, {1e-3, 0.0});
  const Eigen::Vector3d north = visors::astro::offset_on_sky(c, {0.0, 1e-3});
  EXPECT_GT(std::atan2(east.y(), east.x()), 0.0);
  EXPECT_GT(north.z(), 0.0);
}

}  // namespace
