// EopTable: IERS finals2000A parsing (core/files/eop_file.hpp), the table's checks and interpolation.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "visors/core/constants.hpp"
#include "visors/core/eop.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/core/files/eop_file.hpp"
#include "support/temp_file.hpp"

namespace {

using visors::core::EarthOrientation;
using visors::core::EopTable;
using visors::core::files::read_eop_file;
using visors::core::GpsTime;
using visors::core::kArcsecToRad;
using visors::core::TimeScale;

constexpr const char* kFinals = "eop/finals2000A_2024-07-01_2025-01-31.txt";
constexpr double kMasToRad = kArcsecToRad * 1e-3;

GpsTime utc(const char* iso) { return *GpsTime::parse(iso, TimeScale::kUtc); }

std::vector<std::string> real_lines() {
  const auto path = visors::core::files::find_data_file(kFinals);
  std::vector<std::string> lines;
  if (!path) return lines;
  std::ifstream in(*path);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// One finals2000A row in the fixed columns of readme.finals2000A (Bulletin A part only).
std::string finals_line(int yy, int mm, int dd, double mjd, double xp_as, double yp_as,
                        double ut1_utc_s, double lod_ms, double dx_mas, double dy_mas) {
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%2d%2d%2d %8.2f I %9.6f%9.6f %9.6f%9.6f  I%10.7f%10.7f %7.4f%7.4f  I %9.3f%9.3f "
                "%9.3f%9.3f",
                yy, mm, dd, mjd, xp_as, 0.0, yp_as, 0.0, ut1_utc_s, 0.0, lod_ms, 0.0, dx_mas, 0.0,
                dy_mas, 0.0);
  return buf;
}

// A temporary finals2000A file with the given lines.
class TempFile : public visors::test::TempFile {
 public:
  explicit TempFile(const std::vector<std::string>& lines) : visors::test::TempFile(joined(lines), ".txt") {}

 private:
  static std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const auto& l : lines) text += l + '\n';
    return text;
  }
};

class EopFile : public ::testing::Test {
 protected:
  void SetUp() override {
    lines_ = real_lines();
    if (lines_.empty()) {
      GTEST_FAIL() << kFinals << " not found in data/ nor VISORS_DATA_PATH (data/SOURCES.md)";
    }
  }
  std::vector<std::string> lines_;
};

TEST_F(EopFile, LoadsTheWholeFile) {
  const auto table = read_eop_file(*visors::core::files::find_data_file(kFinals));
  ASSERT_TRUE(table.ok()) << table.error().describe();
  EXPECT_EQ(table->size(), 215u);  // data/SOURCES.md: 215 daily rows, MJD 60492..60706
  EXPECT_EQ(table->first_mjd(), 60492.0);
  EXPECT_EQ(table->last_mjd(), 60706.0);
}

TEST_F(EopFile, ValuesAtTheMissionEpochAreTheFileRow) {
  // Row "2410 1 60584.00" of the file (also quoted in SOURCES.md): x_p 0.226101", y_p 0.407871",
  // UT1-UTC 0.0590197 s, LOD 0.0313 ms, dX 0.440 mas, dY -0.027 mas.
  const auto table = read_eop_file(*visors::core::files::find_data_file(kFinals));
  ASSERT_TRUE(table.ok());
  const auto eop = table->at(utc("2024-10-01T00:00:00"));
  ASSERT_TRUE(eop.ok()) << eop.error().describe();
  // round-off of the file's decimal value times the unit (ulp ~2e-22 rad); measured 0 for xp, yp, lod, dx, dy (2026-11)
  EXPECT_NEAR(eop->xp, 0.226101 * kArcsecToRad, 1e-15);
  EXPECT_NEAR(eop->yp, 0.407871 * kArcsecToRad, 1e-15);
  // loose: measured 3.4e-16 s (2026-11), bound 1e-12 ~3000x above round-off (ulp 6.9e-18)
  EXPECT_NEAR(eop->dut1, 0.0590197, 1e-12);
  EXPECT_NEAR(eop->lod, 0.0313e-3, 1e-15);
  EXPECT_NEAR(eop->dx, 0.440 * kMasToRad, 1e-16);
  EXPECT_NEAR(eop->dy, -0.027 * kMasToRad, 1e-16);
}

TEST_F(EopFile, InterpolatesLinearlyBetweenDays) {
  // Midway between 60584 and 60585 (x_p 0.226493", UT1-UTC 0.0589803 s, LOD 0.0948 ms).
  const auto table = read_eop_file(*visors::core::files::find_data_file(kFinals));
  ASSERT_TRUE(table.ok());
  const auto eop = table->at(utc("2024-10-01T12:00:00"));
  ASSERT_TRUE(eop.ok());
  // loose: measured 2.1e-22 / 4.2e-22 rad (2026-11), bound 1e-15 ~1e6x above round-off
  EXPECT_NEAR(eop->xp, 0.5 * (0.226101 + 0.226493) * kArcsecToRad, 1e-15);
  EXPECT_NEAR(eop->yp, 0.5 * (0.407871 + 0.406240) * kArcsecToRad, 1e-15);
  // loose: measured 2.5e-15 s (2026-11), bound 1e-11 ~4000x above
  EXPECT_NEAR(eop->dut1, 0.5 * (0.0590197 + 0.0589803), 1e-11);
  // round-off; measured 0 (2026-11)
  EXPECT_NEAR(eop->lod, 0.5 * (0.0313 + 0.0948) * 1e-3, 1e-15);
  // The last row is inside the table, a second later is not.
  EXPECT_TRUE(table->at(utc("2025-01-31T00:00:00")).ok());
  EXPECT_FALSE(table->at(utc("2025-01-31T00:00:01")).ok());
}

TEST_F(EopFile, OutOfRangeErrorNamesTheRange) {
  const auto table = read_eop_file(*visors::core::files::find_data_file(kFinals));
  ASSERT_TRUE(table.ok());
  const auto eop = table->at(utc("2024-06-30T23:00:00"));
  ASSERT_FALSE(eop.ok());
  const std::string text = eop.error().describe();
  EXPECT_NE(text.find("60492.00"), std::string::npos) << text;
  EXPECT_NE(text.find("60706.00"), std::string::npos) << text;
  EXPECT_NE(text.find("2024-06-30T23:00:00"), std::string::npos) << text;
}

TEST_F(EopFile, TestLineWriterReproducesARealRow) {
  // Guards the synthetic-file tests below: the writer's columns are the file's columns.
  const std::string ours = finals_line(24, 10, 1, 60584.0, 0.226101, 0.407871, 0.0590197, 0.0313,
                                       0.440, -0.027);
  const std::string& real = lines_[92];
  // readme.finals2000A: the Bulletin A columns end at 134 (the loop reads up to 125)
  ASSERT_GE(real.size(), 134u);
  // Compare everything except the error columns, which the writer leaves at zero.
  for (const auto& [first, last] : std::vector<std::pair<int, int>>{
           {1, 27}, {37, 46}, {56, 68}, {79, 86}, {94, 106}, {116, 125}}) {
    EXPECT_EQ(ours.substr(first - 1, last - first + 1), real.substr(first - 1, last - first + 1))
        << "columns " << first << "-" << last;
  }
}

TEST_F(EopFile, CorruptLineIsRejectedWithItsNumber) {
  std::vector<std::string> lines(lines_.begin(), lines_.begin() + 5);
  lines[2][20] = 'x';  // inside x_p, columns 19-27, of line 3
  TempFile file(lines);
  const auto table = read_eop_file(file.path());
  ASSERT_FALSE(table.ok());
  EXPECT_EQ(table.error().field, "line 3");
  EXPECT_NE(table.error().message.find("x_p"), std::string::npos) << table.error().describe();
}

TEST_F(EopFile, DateThatDisagreesWithMjdIsRejected) {
  std::vector<std::string> lines(lines_.begin(), lines_.begin() + 5);
  lines[3][5] = '9';  // 24 7 4 -> 24 7 9
  TempFile file(lines);
  const auto table = read_eop_file(file.path());
  ASSERT_FALSE(table.ok());
  EXPECT_EQ(table.error().field, "line 4");
  EXPECT_NE(table.error().message.find("does not match MJD"), std::string::npos);
}

TEST_F(EopFile, MissingDayIsRejected) {
  std::vector<std::string> lines(lines_.begin(), lines_.begin() + 5);
  lines.erase(lines.begin() + 2);
  TempFile file(lines);
  const auto table = read_eop_file(file.path());
  ASSERT_FALSE(table.ok());
  EXPECT_EQ(table.error().field, "line 3");
  EXPECT_NE(table.error().message.find("consecutive"), std::string::npos);
}

TEST_F(EopFile, TruncatedLineIsRejected) {
  std::vector<std::string> lines(lines_.begin(), lines_.begin() + 5);
  lines[1] = lines[1].substr(0, 30);  // date, MJD and x_p only
  TempFile file(lines);
  const auto table = read_eop_file(file.path());
  ASSERT_FALSE(table.ok());
  EXPECT_EQ(table.error().field, "line 2") << table.error().describe();
}

TEST_F(EopFile, RowWithoutValuesMayOnlyEndTheFile) {
  std::vector<std::string> lines(lines_.begin(), lines_.begin() + 5);
  lines[1] = lines[1].substr(0, 16);  // date and MJD only: a "future" row
  TempFile file(lines);
  const auto table = read_eop_file(file.path());
  ASSERT_FALSE(table.ok());
  EXPECT_EQ(table.error().field, "line 2") << table.error().describe();
  lines.erase(lines.begin() + 2, lines.end());  // now it ends the file: accepted, dropped
  TempFile ending(lines);
  const auto ok = read_eop_file(ending.path());
  ASSERT_TRUE(ok.ok()) << ok.error().describe();
  EXPECT_EQ(ok->size(), 1u);
}

TEST(Eop, MissingFileIsAnError) {
  const auto table = read_eop_file("/nonexistent/finals2000A.txt");
  ASSERT_FALSE(table.ok());
  EXPECT_NE(table.error().message.find("cannot open"), std::string::npos);
}

TEST(Eop, LeapSecondInsideTheIntervalIsInterpolatedThroughUt1MinusTai) {
  // Synthetic rows around the 2016-12-31 leap second. UT1-UTC of MJD 57753 is the IERS
  // finals2000A value, -0.4077601 s; the next day's value is made up, +1 s jump included
  // (0.5922 s). Worked example in docs/algorithms/dynamics.md#earth-orientation-parameters.
  TempFile file({finals_line(16, 12, 30, 57752.0, 0.1, 0.2, -0.4070000, 1.0, 0.1, 0.1),
                 finals_line(16, 12, 31, 57753.0, 0.1, 0.2, -0.4077601, 1.0, 0.1, 0.1),
                 finals_line(17, 1, 1, 57754.0, 0.1, 0.2, 0.5922000, 1.0, 0.1, 0.1),
                 finals_line(17, 1, 2, 57755.0, 0.1, 0.2, 0.5915000, 1.0, 0.1, 0.1)});
  const auto table = read_eop_file(file.path());
  ASSERT_TRUE(table.ok()) << table.error().describe();
  // Noon before the leap: UT1-TAI interpolates (-36.4077601, -36.4078) -> UT1-UTC -0.40778005 s
  // (interpolating UT1-UTC itself would give +0.09).
  const auto noon = table->at(utc("2016-12-31T12:00:00"));
  ASSERT_TRUE(noon.ok());
  // measured regression bound: 2.3e-10 s (2026-11); bound 1e-9 (expected value exact from the two rows)
  EXPECT_NEAR(noon->dut1, -0.40778005, 1e-9);
  const auto new_year = table->at(utc("2017-01-01T00:00:00"));
  ASSERT_TRUE(new_year.ok());
  // loose: measured 1.7e-15 s (2026-11), bound 1e-9 ~6e5x above
  EXPECT_NEAR(new_year->dut1, 0.5922, 1e-9);
  // UT1 itself advances by ~1 s per second straight through 23:59:60.
  GpsTime t = utc("2016-12-31T23:59:58");
  double previous_ut1 = 0.0;
  for (int k = 0; k < 5; ++k, t += 1.0) {
    const auto eop = table->at(t);
    ASSERT_TRUE(eop.ok());
    const auto ut1 = t.jd_ut1(eop->dut1);
    const double ut1_s = ((ut1.jd1 - 2457753.5) + ut1.jd2) * 86400.0;
    if (k > 0) {
      // loose: measured 8.1e-9 s (2026-11), bound 1e-6 ~120x above
      EXPECT_NEAR(ut1_s - previous_ut1, 1.0, 1e-6) << t.format(TimeScale::kUtc);
    }
    previous_ut1 = ut1_s;
  }
}

TEST(Eop, BlankOptionalColumnsReadAsZero) {
  std::string line = finals_line(24, 10, 1, 60584.0, 0.226101, 0.407871, 0.0590197, 0.0313,
                                 0.440, -0.027);
  line = line.substr(0, 78);  // no LOD, dX, dY
  TempFile file({line});
  const auto table = read_eop_file(file.path());
  ASSERT_TRUE(table.ok()) << table.error().describe();
  const auto eop = table->at(utc("2024-10-01T00:00:00"));
  ASSERT_TRUE(eop.ok());
  EXPECT_EQ(eop->lod, 0.0);
  EXPECT_EQ(eop->dx, 0.0);
  // loose: measured 3.4e-16 s (2026-11), bound 1e-12 ~3000x above round-off
  EXPECT_NEAR(eop->dut1, 0.0590197, 1e-12);
}

}  // namespace

namespace {

// The table built in code (as on board, from uplinked values): the rules the reader's line
// errors also enforce. Values: the finals2000A rows of 2024-10-01/02 (x_p, y_p arcsec; UT1-TAI =
// UT1-UTC - 37 s).
std::vector<EopTable::Row> two_days() {
  EopTable::Row first;
  first.mjd = 60584.0;
  first.xp = 0.226101 * kArcsecToRad;
  first.yp = 0.407871 * kArcsecToRad;
  first.ut1_minus_tai = 0.0590197 - 37.0;
  EopTable::Row second = first;
  second.mjd = 60585.0;
  return {first, second};
}

TEST(Eop, TableFromRowsInterpolates) {
  const auto table = EopTable::create(two_days());
  ASSERT_TRUE(table.ok()) << table.error().describe();
  const auto eop = table->at(utc("2024-10-01T12:00:00"));
  ASSERT_TRUE(eop.ok());
  EXPECT_NEAR(eop->dut1, 0.0590197, 1e-12);
}

TEST(Eop, TableWithoutRowsIsRejected) {
  EXPECT_EQ(EopTable::create({}).error().field, "rows");
}

TEST(Eop, TableWithAGapIsRejected) {
  std::vector<EopTable::Row> rows = two_days();
  rows[1].mjd = 60586.0;
  const auto table = EopTable::create(rows);
  ASSERT_FALSE(table.ok());
  EXPECT_EQ(table.error().field, "rows[1]");
  EXPECT_NE(table.error().message.find("consecutive"), std::string::npos);
}

TEST(Eop, TableWithANonFiniteValueIsRejected) {
  std::vector<EopTable::Row> rows = two_days();
  rows[0].xp = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(EopTable::create(rows).error().field, "rows[0]");
}

}  // namespace
