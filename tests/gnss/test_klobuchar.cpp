// The broadcast ionospheric model against IS-GPS-200 (20.3.3.5.2.5, Figure 20-4) evaluated
// independently: the document's step list written out in Python (/usr/bin/python3, double
// precision) with the broadcast coefficients of the IGS file brdc1820.10n (2010-07-01, header
// ION ALPHA / ION BETA). Each case's inputs and the value printed by that script are below.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "visors/gnss/klobuchar.hpp"

namespace {

using visors::gnss::klobuchar_delay_m;
using visors::gnss::KlobucharCoefficients;
using visors::gnss::KlobucharGeometry;

const KlobucharCoefficients kBrdc1820{{0.4657e-08, 0.1490e-07, -0.5960e-07, -0.1192e-06},
                                      {0.8192e+05, 0.8192e+05, -0.6554e+05, -0.5243e+06}};

constexpr double kDeg = std::numbers::pi / 180.0;

// GPS week 1590, day 4 (2010-07-01), plus the time of day.
visors::core::GpsTime at(double time_of_day) {
  return visors::core::GpsTime::from_week_seconds(1590, 4 * 86400.0 + time_of_day).value();
}

double delay(double tod, double lat_deg, double lon_deg, double az_deg, double el_deg) {
  return klobuchar_delay_m(kBrdc1820, KlobucharGeometry{lat_deg * kDeg, lon_deg * kDeg, az_deg * kDeg, el_deg * kDeg}, at(tod))
      .value();
}

// Stanford (37.43 N, 122.17 W), 22:00 GPS = 13:50 local at the pierce point, south at 30 deg.
TEST(Klobuchar, DaytimeMidLatitude) { EXPECT_NEAR(delay(79200.0, 37.43, -122.17, 180.0, 30.0), 4.67051046595555, 1e-9); }

// Zenith, equator, Greenwich, 12:00: F = 1 + 16 (0.53 - 0.5)^3, cosine 2 h before its peak.
TEST(Klobuchar, ZenithAtNoon) { EXPECT_NEAR(delay(43200.0, 0.0, 0.0, 0.0, 90.0), 2.778845759341267, 1e-9); }

// Night (the local time of the pierce point is ~01:00): the 5 ns constant times F at 5 deg.
TEST(Klobuchar, NightTimeConstantAtLowElevation) { EXPECT_NEAR(delay(0.0, 45.0, 10.0, 60.0, 5.0), 4.537037115715541, 1e-9); }

// 78 N looking north: the pierce-point latitude is clamped to 0.416 semicircles.
TEST(Klobuchar, HighLatitudeClamp) { EXPECT_NEAR(delay(30000.0, 78.0, 15.0, 0.0, 20.0), 3.26177921764685, 1e-9); }

// Property of the model: at night the delay is F * 5 ns whatever the coefficients.
TEST(Klobuchar, NightDelayIsFTimesFiveNanoseconds) {
  const double e = 90.0 / 180.0;  // semicircles
  const double f = 1.0 + 16.0 * std::pow(0.53 - e, 3);
  EXPECT_NEAR(delay(0.0, 0.0, 0.0, 0.0, 90.0), f * 5e-9 * 299792458.0, 1e-12);
}

TEST(Klobuchar, ElevationBelowZeroIsRejected) {
  const auto r = klobuchar_delay_m(kBrdc1820, KlobucharGeometry{0.0, 0.0, 0.0, -0.1}, at(0.0));
  EXPECT_EQ(r.error().field, "el");
}

TEST(Klobuchar, LatitudeBeyondThePoleIsRejected) {
  const auto r = klobuchar_delay_m(kBrdc1820, KlobucharGeometry{2.0, 0.0, 0.0, 0.5}, at(0.0));
  EXPECT_EQ(r.error().field, "lat");
}

TEST(Klobuchar, NonFiniteCoefficientIsRejected) {
  KlobucharCoefficients bad = kBrdc1820;
  bad.beta[2] = std::nan("");
  EXPECT_EQ(klobuchar_delay_m(bad, KlobucharGeometry{0.0, 0.0, 0.0, 0.5}, at(0.0)).error().field, "beta");
}

}  // namespace

namespace {

using visors::gnss::klobuchar_topside_delay_m;

// Topside scaling (klobuchar.hpp), evaluated by hand in Python from the zenith-at-noon case:
// vertical = 0.35 * 2.778845759341267 / (1 + 16 * 0.03^3) = 0.9721760357220115 m; at 30 deg and
// 500 km with the 1000 km shell, M = 1 / sqrt(1 - (6871 cos 30 / 7371)^2): 1.6472850292723484 m;
// below the horizon, M(0): 2.685349576290729 m. Azimuth 0 as in the ground case (the zenith pierce
// point moves with the azimuth by 5e-4 semicircle).
TEST(KlobucharTopside, ZenithIsTheFractionOfTheVerticalColumn) {
  const KlobucharGeometry g{0.0, 0.0, 0.0, 90.0 * kDeg};
  EXPECT_NEAR(klobuchar_topside_delay_m(kBrdc1820, g, 500e3, at(43200.0)).value(), 0.9721760357220115, 1e-12);
}

TEST(KlobucharTopside, ThinShellMappingAtThirtyDegrees) {
  const KlobucharGeometry g{0.0, 0.0, 0.0, 30.0 * kDeg};
  EXPECT_NEAR(klobuchar_topside_delay_m(kBrdc1820, g, 500e3, at(43200.0)).value(), 1.6472850292723484, 1e-12);
}

TEST(KlobucharTopside, RaysBelowTheHorizontalUseTheHorizontalMapping) {
  const KlobucharGeometry g{0.0, 0.0, 0.0, -10.0 * kDeg};
  EXPECT_NEAR(klobuchar_topside_delay_m(kBrdc1820, g, 500e3, at(43200.0)).value(), 2.685349576290729, 1e-12);
}

TEST(KlobucharTopside, ShellBelowTheReceiverIsRejected) {
  const auto delay = klobuchar_topside_delay_m(kBrdc1820, {0.0, 0.0, 0.0, 1.0}, 500e3, at(0.0), {0.35, 400e3});
  ASSERT_FALSE(delay.ok());
  EXPECT_EQ(delay.error().field, "shell_height_m");
}

}  // namespace

namespace {

using visors::gnss::klobuchar_topside_delay_m;

// The topside model is continuous across the ground model's night cut-off (klobuchar.hpp,
// "Continuity"). Zenith at the equator and Greenwich (pierce point there, M = 1), brdc1820: the
// period is 83 800 s (beta at phi_m = 0.064 cos(-1.617 pi) = 0.0232 semicircle) and x reaches 1.57
// at ~71 340 s GPS time of day. Sampled every second over [70 000, 73 000] s: the ground model
// jumps there by 0.0207 x amplitude x F x c = 0.0207 x 5.0e-9 s x 1.0004 x c = 0.031 m; the
// topside's largest step between seconds is its rate, at most 0.35 x A x (2 pi / P) x c = 4e-5 m
// per second before the kink (bound 1e-4 m). Away from the band 1.57 <= |x| < 1.5925 the topside
// is the scaled ground model: 0.35 x ground / F(90 deg) at the zenith (M = 1).
TEST(KlobucharTopside, ContinuousAcrossTheNightCutOff) {
  const KlobucharGeometry zenith{0.0, 0.0, 0.0, 90.0 * kDeg};
  const double f_zenith = 1.0 + 16.0 * std::pow(0.53 - 0.5, 3);
  double largest_topside_step = 0.0, largest_ground_step = 0.0, agree_worst = 0.0;
  double previous_topside = klobuchar_topside_delay_m(kBrdc1820, zenith, 500e3, at(70000.0)).value();
  double previous_ground = klobuchar_delay_m(kBrdc1820, zenith, at(70000.0)).value();
  for (double tod = 70001.0; tod <= 73000.0; tod += 1.0) {
    const double topside = klobuchar_topside_delay_m(kBrdc1820, zenith, 500e3, at(tod)).value();
    const double ground = klobuchar_delay_m(kBrdc1820, zenith, at(tod)).value();
    largest_topside_step = std::max(largest_topside_step, std::abs(topside - previous_topside));
    largest_ground_step = std::max(largest_ground_step, std::abs(ground - previous_ground));
    // outside the band (71 340 .. 71 640 s with this period): the scaled ground model
    if (tod < 71300.0 || tod > 71700.0) agree_worst = std::max(agree_worst, std::abs(topside - 0.35 * ground / f_zenith));
    previous_topside = topside;
    previous_ground = ground;
  }
  std::printf("largest step per second: ground %.5f m, topside %.2e m; topside vs scaled ground %.1e m\n",
              largest_ground_step, largest_topside_step, agree_worst);
  EXPECT_NEAR(largest_ground_step, 0.031, 0.002);  // the standard's jump is there (precondition)
  EXPECT_LT(largest_topside_step, 1e-4);
  EXPECT_LT(agree_worst, 1e-12);
}

}  // namespace
