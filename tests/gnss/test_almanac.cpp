// GPS almanac: the user algorithm against an independent Keplerian evaluation, and the YUMA and
// SEM readers on texts written after the NAVCEN formats (the same satellite in both).
#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <string_view>

#include "visors/gnss/almanac.hpp"
#include "visors/gnss/files/almanac_file.hpp"
#include "visors/gnss/gps_constants.hpp"
#include "support/temp_file.hpp"

namespace visors::gnss {
namespace {

core::GpsTime gps(const char* iso) { return core::GpsTime::parse(iso, core::TimeScale::kGps).value(); }

// An almanac entry with values rounded from the G12 broadcast record of brdc1820.10n at 12:00
// (line 1817): a realistic GPS orbit.
GpsAlmanacEntry g12() {
  GpsAlmanacEntry a;
  a.prn = 12;
  a.eccentricity = 0.00586;
  a.toa = gps("2010-07-01T12:00:00");
  a.inclination_rad = 0.9554;
  a.raan_rate_radps = -8.1e-9;
  a.sqrt_a = 5153.6;
  a.raan_rad = -0.4214;
  a.arg_perigee_rad = 0.7826;
  a.mean_anomaly_rad = 2.1;
  a.af0_s = -9.8e-5;
  a.af1_sps = 4.1e-12;
  return a;
}

// Independent method: rotation of the perifocal position by Eigen angle-axis rotations
// R3(Omega_k) R1(i) R3(omega), Kepler's equation by fixed-point iteration (not Newton).
Eigen::Vector3d kepler_ecef(const GpsAlmanacEntry& a, core::GpsTime t) {
  const double tk = t.seconds_since(a.toa);
  const double semi_major = a.sqrt_a * a.sqrt_a;
  const double m = a.mean_anomaly_rad + std::sqrt(kGpsMu / std::pow(semi_major, 3)) * tk;
  double e_anomaly = m;
  for (int k = 0; k < 60; ++k) e_anomaly = m + a.eccentricity * std::sin(e_anomaly);
  const Eigen::Vector3d perifocal(semi_major * (std::cos(e_anomaly) - a.eccentricity),
                                  semi_major * std::sqrt(1.0 - a.eccentricity * a.eccentricity) * std::sin(e_anomaly), 0.0);
  const double node = a.raan_rad + (a.raan_rate_radps - kGpsEarthRate) * tk - kGpsEarthRate * a.toa.seconds_of_week();
  return (Eigen::AngleAxisd(node, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(a.inclination_rad, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(a.arg_perigee_rad, Eigen::Vector3d::UnitZ()) * perifocal);
}

TEST(Almanac, PositionMatchesAnIndependentKeplerEvaluation) {
  const GpsAlmanacEntry a = g12();
  for (double dt : {-86400.0, -3600.0, 0.0, 5400.0, 3.5 * 86400.0}) {
    const core::GpsTime t = a.toa + dt;
    // independent method (comment above); loose: measured 1.9e-8 m (2026-11), bound 1e-3 m ~5e4x above
    EXPECT_LT((almanac_state(a, t).r_ecef_m - kepler_ecef(a, t)).norm(), 1e-3) << dt;
  }
}

TEST(Almanac, VelocityIsTheDerivativeOfPosition) {
  const GpsAlmanacEntry a = g12();
  const core::GpsTime t = a.toa + 7200.0;
  const Eigen::Vector3d numeric = almanac_state(a, t + 0.5).r_ecef_m - almanac_state(a, t - 0.5).r_ecef_m;
  // measured regression bound: 3.1e-6 m/s (2026-11); bound 1e-5 m/s
  EXPECT_LT((almanac_state(a, t).v_ecef_mps - numeric).norm(), 1e-5);
}

TEST(Almanac, ValidateNamesTheField) {
  GpsAlmanacEntry a = g12();
  a.eccentricity = 0.3;
  ASSERT_FALSE(validate(a).ok());
  EXPECT_EQ(std::string_view(validate(a).field()), "eccentricity");
}

// The same satellite in both formats (YUMA in radians; SEM in semicircles with the inclination
// as an offset from 0.30 semicircles: 0.9554 rad = 0.304115... sc -> offset 0.00411546...).
constexpr const char* kYuma =
    "******** Week 566 almanac for PRN-12 ********\n"
    "ID:                         12\n"
    "Health:                     000\n"
    "Eccentricity:               0.5860000000E-002\n"
    "Time of Applicability(s):  388800.0000\n"
    "Orbital Inclination(rad):   0.9554000000\n"
    "Rate of Right Ascen(r/s):  -0.8100000000E-008\n"
    "SQRT(A)  (m 1/2):           5153.600000\n"
    "Right Ascen at Week(rad):  -0.4214000000E+000\n"
    "Argument of Perigee(rad):   0.782600000\n"
    "Mean Anom(rad):             0.2100000000E+001\n"
    "Af0(s):                    -0.9800000000E-004\n"
    "Af1(s/s):                   0.4100000000E-011\n"
    "week:                        566\n"
    "\n";

std::string sem_text() {
  const double sc = kGpsPi;
  char text[1024];
  std::snprintf(text, sizeof text,
                " 1 TEST.ALM\n"
                " 566 388800\n"
                "\n"
                "12\n"
                "61\n"
                "0\n"
                " %.15E %.15E %.15E\n"
                " %.15E %.15E %.15E\n"
                " %.15E %.15E %.15E\n"
                "0\n"
                "9\n",
                0.00586, 0.9554 / sc - 0.30, -8.1e-9 / sc, 5153.6, -0.4214 / sc, 0.7826 / sc, 2.1 / sc, -9.8e-5, 4.1e-12);
  return text;
}

void expect_g12(const GpsAlmanacEntry& e) {
  const GpsAlmanacEntry r = g12();
  EXPECT_EQ(e.prn, 12);
  EXPECT_EQ(e.toa, r.toa);  // week 566 + 1024 = 1590, resolved near 2010
  // the same values in both formats (comment above), round-off; measured 0, 0, 1.7e-24 rad/s, 0, 1.1e-16 rad, 0, 0 (2026-11)
  EXPECT_NEAR(e.eccentricity, r.eccentricity, 1e-15);
  EXPECT_NEAR(e.inclination_rad, r.inclination_rad, 1e-13);
  EXPECT_NEAR(e.raan_rate_radps, r.raan_rate_radps, 1e-22);
  EXPECT_NEAR(e.raan_rad, r.raan_rad, 1e-13);
  EXPECT_NEAR(e.arg_perigee_rad, r.arg_perigee_rad, 1e-13);
  EXPECT_NEAR(e.mean_anomaly_rad, r.mean_anomaly_rad, 1e-13);
  EXPECT_NEAR(e.af0_s, r.af0_s, 1e-18);
}

TEST(AlmanacFiles, YumaBlock) {
  test::TempFile file(kYuma, ".alm");
  const auto entries = files::read_yuma_almanac(file.path(), gps("2010-07-01T00:00:00"));
  ASSERT_TRUE(entries.ok()) << entries.error().describe();
  ASSERT_EQ(entries->size(), 1u);
  expect_g12(entries->front());
}

TEST(AlmanacFiles, SemRecordGivesTheSameEntry) {
  test::TempFile file(sem_text(), ".al3");
  const auto entries = files::read_sem_almanac(file.path(), gps("2010-07-01T00:00:00"));
  ASSERT_TRUE(entries.ok()) << entries.error().describe();
  ASSERT_EQ(entries->size(), 1u);
  expect_g12(entries->front());
}

// The week modulo 1024 resolves to the cycle nearest the given time: 566 -> 2614 near 2030.
TEST(AlmanacFiles, WeekRolloverIsResolvedNearTheGivenTime) {
  test::TempFile file(kYuma, ".alm");
  const auto entries = files::read_yuma_almanac(file.path(), gps("2030-02-01T00:00:00"));
  ASSERT_TRUE(entries.ok());
  EXPECT_EQ(entries->front().toa.week(), 566 + 2048);
}

TEST(AlmanacFiles, YumaWrongKeyNamesFileAndLine) {
  std::string text = kYuma;
  text.replace(text.find("Eccentricity"), 12, "Excentricity");
  test::TempFile file(text, ".alm");
  const auto entries = files::read_yuma_almanac(file.path(), gps("2010-07-01T00:00:00"));
  ASSERT_FALSE(entries.ok());
  EXPECT_EQ(entries.error().field, file.path().string() + ":4");
}

TEST(AlmanacFiles, YumaBadNumberAndTruncatedBlock) {
  std::string text = kYuma;
  text.replace(text.find("5153.600000"), 4, "51x3");
  test::TempFile bad(text, ".alm");
  const auto a = files::read_yuma_almanac(bad.path(), gps("2010-07-01T00:00:00"));
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.error().field, bad.path().string() + ":8");
  std::string cut = kYuma;
  cut = cut.substr(0, cut.find("Af0"));
  test::TempFile truncated(cut, ".alm");
  const auto b = files::read_yuma_almanac(truncated.path(), gps("2010-07-01T00:00:00"));
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.error().message.find("truncated"), std::string::npos) << b.error().message;
}

TEST(AlmanacFiles, SemShortLineNamesFileAndLine) {
  std::string text = sem_text();
  const std::size_t eighth = [&] {
    std::size_t at = 0;
    for (int k = 0; k < 7; ++k) at = text.find('\n', at) + 1;
    return at;
  }();
  text.replace(eighth, text.find('\n', eighth) - eighth, " 5153.6 -0.134");
  test::TempFile file(text, ".al3");
  const auto entries = files::read_sem_almanac(file.path(), gps("2010-07-01T00:00:00"));
  ASSERT_FALSE(entries.ok());
  EXPECT_EQ(entries.error().field, file.path().string() + ":8");
  EXPECT_NE(entries.error().message.find("expected 3 numbers"), std::string::npos) << entries.error().message;
}

}  // namespace
}  // namespace visors::gnss
