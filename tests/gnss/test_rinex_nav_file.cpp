// RINEX 2.11 and 3.x navigation files: the real files of data/gnss and malformed copies.
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "visors/gnss/files/rinex_nav_file.hpp"
#include "gnss_test_data.hpp"
#include "support/temp_file.hpp"

namespace visors::gnss::files {
namespace {

core::GpsTime gps(const char* iso) { return core::GpsTime::parse(iso, core::TimeScale::kGps).value(); }

// Reference: the header and first record of brdc1820.10n (lines 4-16, quoted values).
TEST(RinexNav, Rinex2HeaderAndFirstRecord) {
  VISORS_REQUIRE_GNSS_DATA(test::kBrdc20100701);
  const auto nav = read_rinex_navigation(test::gnss_data(test::kBrdc20100701));
  ASSERT_TRUE(nav.ok()) << nav.error().describe();
  EXPECT_DOUBLE_EQ(nav->version, 2.0);
  ASSERT_TRUE(nav->ionosphere.has_value());
  EXPECT_DOUBLE_EQ(nav->ionosphere->alpha[0], 0.4657e-08);
  EXPECT_DOUBLE_EQ(nav->ionosphere->beta[3], -0.5243e+06);
  EXPECT_EQ(nav->leap_seconds, 15);
  const auto& g01 = nav->records.front();
  EXPECT_EQ(g01.prn, 1);
  EXPECT_EQ(g01.toc, gps("2010-07-01T00:00:00"));
  EXPECT_DOUBLE_EQ(g01.af0_s, -0.136290676892e-03);
  EXPECT_DOUBLE_EQ(g01.sqrt_a, 0.515480139732e+04);
  EXPECT_EQ(g01.toe, gps("2010-07-01T00:00:00"));  // week 1590, 345600 s
  EXPECT_EQ(g01.health, 63);
  EXPECT_DOUBLE_EQ(g01.tgd_s, -0.190921127796e-07);
  EXPECT_EQ(g01.iodc, 63);
  EXPECT_EQ(g01.transmission, gps("2010-07-01T00:00:00") + (341670.0 - 345600.0));
  EXPECT_EQ(nav->record_lines.front(), 9u);
  EXPECT_EQ(nav->records.size(), 421u);  // 8-line records after the 8-line header (grep count)
}

// Reference: SOURCES.md section 4 (231 records, G01-G32; HERT mixes D and E exponents) and the
// file's header lines 3-6.
TEST(RinexNav, Rinex304HertFile) {
  VISORS_REQUIRE_GNSS_DATA(test::kHert2024);
  const auto nav = read_rinex_navigation(test::gnss_data(test::kHert2024));
  ASSERT_TRUE(nav.ok()) << nav.error().describe();
  EXPECT_DOUBLE_EQ(nav->version, 3.04);
  EXPECT_EQ(nav->records.size(), 231u);
  std::set<int> prns;
  for (const auto& r : nav->records) prns.insert(r.prn);
  EXPECT_EQ(prns.size(), 32u);
  ASSERT_TRUE(nav->ionosphere.has_value());
  EXPECT_DOUBLE_EQ(nav->ionosphere->alpha[0], 2.6077e-08);
  EXPECT_DOUBLE_EQ(nav->ionosphere->beta[1], 1.6384e+04);
  EXPECT_EQ(nav->leap_seconds, 18);
  // The stale G01 record (t_oe week 2270 = 2023-07-10, SOURCES.md): t_oe 144000 s of week 2270.
  EXPECT_EQ(nav->records.front().toe, core::GpsTime::from_week_seconds(2270, 144000.0).value());
  EXPECT_DOUBLE_EQ(nav->records.front().fit_interval_h, 6.0);  // fit field "1" = the ICD flag
}

TEST(RinexNav, Rinex305NyaFile) {
  VISORS_REQUIRE_GNSS_DATA(test::kNya2024);
  const auto nav = read_rinex_navigation(test::gnss_data(test::kNya2024));
  ASSERT_TRUE(nav.ok()) << nav.error().describe();
  EXPECT_EQ(nav->records.size(), 216u);  // SOURCES.md: 216 records, 31 PRNs, G01 absent
  std::set<int> prns;
  for (const auto& r : nav->records) prns.insert(r.prn);
  EXPECT_EQ(prns.size(), 31u);
  EXPECT_EQ(prns.count(1), 0u);
  EXPECT_EQ(nav->records.front().toc, gps("2024-05-07T02:00:00"));
}

// Malformed copies of brdc1820.10n: each error names the file and the line.
using RinexNavMalformed = test::MalformedCopy<test::kBrdc20100701>;

TEST_F(RinexNavMalformed, BadNumberNamesFileLineAndColumns) {
  // Line 11 = broadcast orbit 2 of the first record; sqrt(A) garbled.
  test::TempFile file(with_line(11, "   -0.476092100143D-05 0.483528291807D-02 0.545941293240D-05 0.51548X139732D+04"), ".10n");
  const auto nav = read_rinex_navigation(file.path());
  ASSERT_FALSE(nav.ok());
  EXPECT_EQ(nav.error().field, file.path().string() + ":11");
  EXPECT_NE(nav.error().message.find("sqrt(A)"), std::string::npos) << nav.error().message;
}

TEST_F(RinexNavMalformed, TruncatedRecordNamesTheLastLine) {
  // Keep the header and 5 lines of the first record.
  test::TempFile file(test::first_lines(text_, 13), ".10n");
  const auto nav = read_rinex_navigation(file.path());
  ASSERT_FALSE(nav.ok());
  EXPECT_EQ(nav.error().field, file.path().string() + ":13");
  EXPECT_NE(nav.error().message.find("truncated"), std::string::npos) << nav.error().message;
}

TEST_F(RinexNavMalformed, MissingRequiredValue) {
  // Line 12 (orbit 3) with t_oe blank.
  test::TempFile file(with_line(12, "                       0.558793544769D-08 0.292603518708D+01-0.931322574615D-07"), ".10n");
  const auto nav = read_rinex_navigation(file.path());
  ASSERT_FALSE(nav.ok());
  EXPECT_EQ(nav.error().field, file.path().string() + ":9");  // the record's first line
  EXPECT_NE(nav.error().message.find("Toe"), std::string::npos) << nav.error().message;
}

TEST_F(RinexNavMalformed, HeaderWithoutEnd) {
  test::TempFile file("     2              NAVIGATION DATA                         RINEX VERSION / TYPE\n", ".10n");
  const auto nav = read_rinex_navigation(file.path());
  ASSERT_FALSE(nav.ok());
  EXPECT_EQ(nav.error().field, file.path().string());
  EXPECT_NE(nav.error().message.find("END OF HEADER"), std::string::npos);
}

TEST_F(RinexNavMalformed, ObservationFileIsRejected) {
  test::TempFile file(with_line(1, "     2              OBSERVATION DATA    G (GPS)             RINEX VERSION / TYPE"), ".10n");
  const auto nav = read_rinex_navigation(file.path());
  ASSERT_FALSE(nav.ok());
  EXPECT_EQ(nav.error().field, file.path().string() + ":1");
}

TEST_F(RinexNavMalformed, BadEpochNamesTheField) {
  test::TempFile file(with_line(9, " 1 10 13  1  0  0  0.0-0.136290676892D-03-0.397903932026D-11 0.000000000000D+00"), ".10n");
  const auto nav = read_rinex_navigation(file.path());
  ASSERT_FALSE(nav.ok());
  EXPECT_EQ(nav.error().field, file.path().string() + ":9");
  EXPECT_NE(nav.error().message.find("t_oc"), std::string::npos) << nav.error().message;
}

TEST(RinexNav, MissingFile) {
  const auto nav = read_rinex_navigation("/nonexistent/brdc0010.10n");
  ASSERT_FALSE(nav.ok());
  EXPECT_EQ(nav.error().field, "/nonexistent/brdc0010.10n");
}

}  // namespace
}  // namespace visors::gnss::files

namespace visors::gnss::files {
namespace {

// Writing brdc1820.10n as RINEX 3.05 and reading it back gives every record again, to the
// 12-digit mantissa of the format (relative 5e-13) and exactly for the integers and times.
TEST(RinexNav, Rinex3WriteReadRoundTrip) {
  VISORS_REQUIRE_GNSS_DATA(test::kBrdc20100701);
  const auto original = read_rinex_navigation(test::gnss_data(test::kBrdc20100701));
  ASSERT_TRUE(original.ok());
  test::TempFile file("", ".rnx");
  ASSERT_TRUE(write_rinex3_navigation(file.path(), *original, "visors test").ok());
  const auto again = read_rinex_navigation(file.path());
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_DOUBLE_EQ(again->version, 3.05);
  ASSERT_EQ(again->records.size(), original->records.size());
  EXPECT_EQ(again->leap_seconds, 15);
  EXPECT_DOUBLE_EQ(again->ionosphere->beta[2], original->ionosphere->beta[2]);
  const auto close = [](double a, double b) { return std::abs(a - b) <= 5e-13 * std::abs(b) + 1e-300; };
  for (std::size_t k = 0; k < original->records.size(); ++k) {
    const auto& a = original->records[k];
    const auto& b = again->records[k];
    EXPECT_EQ(a.prn, b.prn);
    EXPECT_EQ(a.toc, b.toc);
    EXPECT_EQ(a.toe, b.toe);
    EXPECT_EQ(a.transmission, b.transmission);
    EXPECT_EQ(a.iode, b.iode);
    EXPECT_EQ(a.iodc, b.iodc);
    EXPECT_EQ(a.health, b.health);
    for (const auto& [x, y] : {std::pair{a.af0_s, b.af0_s}, {a.sqrt_a, b.sqrt_a}, {a.eccentricity, b.eccentricity},
                               {a.m0_rad, b.m0_rad}, {a.omega0_rad, b.omega0_rad}, {a.omega_dot_radps, b.omega_dot_radps},
                               {a.cuc_rad, b.cuc_rad}, {a.crs_m, b.crs_m}, {a.tgd_s, b.tgd_s}, {a.i0_rad, b.i0_rad}}) {
      EXPECT_TRUE(close(y, x)) << k << ": " << x << " vs " << y;
    }
  }
}

}  // namespace
}  // namespace visors::gnss::files
