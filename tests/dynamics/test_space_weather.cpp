// CelesTrak space-weather CSV: NRLMSISE-00 convention at the mission epoch and the October 2024
// storm (the file's rows; docs/algorithms/dynamics.md#space-weather), range and format errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "visors/core/files/data_path.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/dynamics/files/space_weather_file.hpp"
#include "visors/dynamics/space_weather.hpp"
#include "support/temp_file.hpp"

namespace {

using visors::core::GpsTime;
using visors::core::TimeScale;
using visors::dynamics::SpaceWeatherTable;
using visors::dynamics::files::read_space_weather_file;

constexpr char kFile[] = "space_weather/SW-Observed_2024-07-01_2025-01-31.csv";

GpsTime utc(const char* iso) { return *GpsTime::parse(iso, TimeScale::kUtc); }

class SpaceWeatherFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto path = visors::core::files::find_data_file(kFile);
    if (!path) GTEST_FAIL() << kFile << " not found in data/ nor VISORS_DATA_PATH (data/SOURCES.md)";
    auto table = read_space_weather_file(*path);
    ASSERT_TRUE(table.ok()) << table.error().describe();
    table_ = std::move(table).value();
  }
  std::optional<SpaceWeatherTable> table_;
};

TEST_F(SpaceWeatherFile, CoversThe215Days) {
  EXPECT_EQ(table_->size(), 215u);        // data/SOURCES.md: 215 days
  EXPECT_EQ(table_->first_mjd(), 60492);  // 2024-07-01
  EXPECT_EQ(table_->last_mjd(), 60706);   // 2025-01-31
}

TEST_F(SpaceWeatherFile, MissionEpochCentredMeanAndAp) {
  // File row 2024-10-01: F10.7_OBS_CENTER81 215.3, AP_AVG 5.
  const auto a = table_->at(utc("2024-10-01T12:00:00"));
  ASSERT_TRUE(a.ok()) << a.error().describe();
  EXPECT_EQ(a->f107a, 215.3);
  EXPECT_EQ(a->ap, 5.0);
}

TEST_F(SpaceWeatherFile, F107IsThePreviousDaysObservedValue) {
  // File row 2024-10-01: F10.7_OBS 244.6, so f107 = 244.6 during 2024-10-02 UTC.
  EXPECT_EQ(table_->at(utc("2024-10-02T00:00:00"))->f107, 244.6);
  EXPECT_EQ(table_->at(utc("2024-10-02T23:59:59.999"))->f107, 244.6);
  // ... and on 2024-10-01 the 2024-09-30 value (file row 2024-09-30: F10.7_OBS 214.2).
  EXPECT_EQ(table_->at(utc("2024-10-01T00:00:00"))->f107, 214.2);
}

TEST_F(SpaceWeatherFile, StormDaysDailyAp) {
  // File rows: AP_AVG 97 on 2024-10-10 and 116 on 2024-10-11.
  EXPECT_EQ(table_->at(utc("2024-10-10T06:00:00"))->ap, 97.0);
  EXPECT_EQ(table_->at(utc("2024-10-11T18:00:00"))->ap, 116.0);
}

TEST_F(SpaceWeatherFile, ThreeHourlyApOfTheCurrentInterval) {
  // File row 2024-10-10: AP1..AP8 = 7,12,5,12,22,179,236,300.
  EXPECT_EQ(*table_->ap_3hourly(utc("2024-10-10T00:00:00")), 7.0);
  EXPECT_EQ(*table_->ap_3hourly(utc("2024-10-10T17:59:59")), 179.0);
  EXPECT_EQ(*table_->ap_3hourly(utc("2024-10-10T21:00:00")), 300.0);
}

TEST_F(SpaceWeatherFile, OutsideTheRangeIsAnErrorNamingTheRange) {
  const auto before = table_->at(utc("2024-07-01T12:00:00"));  // no previous day for f107
  ASSERT_FALSE(before.ok());
  EXPECT_EQ(before.error().field, "t");
  EXPECT_NE(before.error().message.find("2024-07-02T00:00:00 .. 2025-01-31T24:00:00"),
            std::string::npos)
      << before.error().message;
  EXPECT_FALSE(table_->at(utc("2025-02-01T00:00:00")).ok());
  EXPECT_TRUE(table_->at(utc("2025-01-31T23:59:59")).ok());
  EXPECT_TRUE(table_->ap_3hourly(utc("2024-07-01T00:00:00")).ok());
}

// A temporary CSV file with the given text.
class TempCsv : public visors::test::TempFile {
 public:
  explicit TempCsv(const std::string& text) : TempFile(text, ".csv") {}
};

// A reordered header (columns are found by name) and two rows.
constexpr char kHeader[] = "AP_AVG,DATE,F10.7_OBS_CENTER81,AP1,AP2,AP3,AP4,AP5,AP6,AP7,AP8,F10.7_OBS\n";
constexpr char kRow1[] = "5,2024-10-01,215.3,5,7,5,3,4,7,5,4,244.6\n";

TEST(SpaceWeatherReader, ColumnsAreFoundByName) {
  const TempCsv f(std::string(kHeader) + kRow1 + "5,2024-10-02,214.7,7,6,6,5,7,3,5,4,274.4\n");
  const auto t = read_space_weather_file(f.path());
  ASSERT_TRUE(t.ok()) << t.error().describe();
  const auto a = t->at(utc("2024-10-02T12:00:00"));
  ASSERT_TRUE(a.ok()) << a.error().describe();
  EXPECT_EQ(a->f107, 244.6);
  EXPECT_EQ(a->f107a, 214.7);
  EXPECT_EQ(*t->ap_3hourly(utc("2024-10-02T03:00:00")), 6.0);
}

TEST(SpaceWeatherReader, MalformedNumberNamesLineAndColumn) {
  const TempCsv f(std::string(kHeader) + kRow1 + "5,2024-10-02,214.7,7,6,6,5,7,3,5,4,27x4.4\n");
  const auto t = read_space_weather_file(f.path());
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().field, "line 3");
  EXPECT_NE(t.error().message.find("F10.7_OBS"), std::string::npos) << t.error().message;
}

TEST(SpaceWeatherReader, BlankFieldIsRejected) {
  const TempCsv f(std::string(kHeader) + kRow1 + "5,2024-10-02,214.7,7,6,6,5,,3,5,4,274.4\n");
  const auto t = read_space_weather_file(f.path());
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().field, "line 3");
  EXPECT_NE(t.error().message.find("AP5"), std::string::npos) << t.error().message;
}

TEST(SpaceWeatherReader, MissingDayIsRejected) {
  const TempCsv f(std::string(kHeader) + kRow1 + "5,2024-10-03,214.7,7,6,6,5,7,3,5,4,274.4\n");
  const auto t = read_space_weather_file(f.path());
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().field, "line 3");
  EXPECT_NE(t.error().message.find("DATE"), std::string::npos) << t.error().message;
}

TEST(SpaceWeatherReader, BadDateIsRejected) {
  const TempCsv f(std::string(kHeader) + "5,2024-13-01,215.3,5,7,5,3,4,7,5,4,244.6\n");
  EXPECT_EQ(read_space_weather_file(f.path()).error().field, "line 2");
}

TEST(SpaceWeatherReader, MissingColumnIsNamed) {
  const TempCsv f("DATE,F10.7_OBS\n2024-10-01,244.6\n");
  const auto t = read_space_weather_file(f.path());
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().field, "line 1");
  EXPECT_NE(t.error().message.find("F10.7_OBS_CENTER81"), std::string::npos) << t.error().message;
}

TEST(SpaceWeatherReader, MissingFileIsAnError) {
  EXPECT_FALSE(read_space_weather_file("/nonexistent/sw.csv").ok());
}

// The table built in code (as on board, from uplinked values): the rules the reader's line
// errors also enforce. Values: the CelesTrak rows of 2024-10-01/02 (MJD 60584/60585).
std::vector<SpaceWeatherTable::Day> two_days() {
  SpaceWeatherTable::Day first{"2024-10-01", 244.6, 215.3, 5.0, {5, 7, 5, 3, 4, 7, 5, 4}};
  SpaceWeatherTable::Day second{"2024-10-02", 274.4, 214.7, 5.0, {7, 6, 6, 5, 7, 3, 5, 4}};
  return {first, second};
}

TEST(SpaceWeatherTable, FromDaysFollowsTheNrlmsiseConvention) {
  const auto t = SpaceWeatherTable::create(60584, two_days());
  ASSERT_TRUE(t.ok()) << t.error().describe();
  const auto a = t->at(utc("2024-10-02T12:00:00"));
  ASSERT_TRUE(a.ok()) << a.error().describe();
  EXPECT_EQ(a->f107, 244.6);
  EXPECT_EQ(a->f107a, 214.7);
}

TEST(SpaceWeatherTable, OneDayIsRejected) {
  auto days = two_days();
  days.pop_back();
  EXPECT_EQ(SpaceWeatherTable::create(60584, days).error().field, "days");
}

TEST(SpaceWeatherTable, NonPositiveF107IsRejected) {
  auto days = two_days();
  days[1].f107_obs_center81 = 0.0;
  EXPECT_EQ(SpaceWeatherTable::create(60584, days).error().field, "days[1]");
}

TEST(SpaceWeatherTable, NegativeApIsRejected) {
  auto days = two_days();
  days[0].ap[7] = -1.0;
  EXPECT_EQ(SpaceWeatherTable::create(60584, days).error().field, "days[0]");
}

// The NRLMSISE-00 ap array (the model's documentation of its AP input, e.g. the NRL gtd7 comment:
// daily Ap; 3-hourly ap now, 3, 6, 9 h before; the means of the eight from 12 to 33 h and from 36
// to 57 h before). Synthetic days whose interval i of day d has ap = 10 d + i, so each expected
// element is computed by hand below.
std::vector<SpaceWeatherTable::Day> numbered_days() {
  std::vector<SpaceWeatherTable::Day> days;
  for (int d = 0; d < 3; ++d) {
    SpaceWeatherTable::Day day{"2024-10-0" + std::to_string(d + 1), 200.0, 200.0, 90.0 + d, {}};
    for (int i = 0; i < 8; ++i) day.ap[static_cast<std::size_t>(i)] = 10.0 * d + i;
    days.push_back(day);
  }
  return days;
}

TEST(SpaceWeatherTable, ApHistoryFollowsTheNrlmsiseDefinition) {
  const auto t = SpaceWeatherTable::create(60584, numbered_days()).value();
  // 2024-10-03 13:30 UTC: day 2, interval 4 (12-15 UTC).
  const auto ap = t.ap_history(utc("2024-10-03T13:30:00"));
  ASSERT_TRUE(ap.ok()) << ap.error().describe();
  EXPECT_EQ((*ap)[0], 92.0);  // daily Ap of day 2
  EXPECT_EQ((*ap)[1], 24.0);  // current interval
  EXPECT_EQ((*ap)[2], 23.0);  // 3 h before
  EXPECT_EQ((*ap)[3], 22.0);  // 6 h before
  EXPECT_EQ((*ap)[4], 21.0);  // 9 h before
  // 12..33 h before: day 2 interval 0 and day 1 intervals 7..1: (20 + 17 + ... + 11) / 8.
  EXPECT_EQ((*ap)[5], (20.0 + 17 + 16 + 15 + 14 + 13 + 12 + 11) / 8.0);
  // 36..57 h before: day 1 interval 0 and day 0 intervals 7..1: (10 + 7 + ... + 1) / 8.
  EXPECT_EQ((*ap)[6], (10.0 + 7 + 6 + 5 + 4 + 3 + 2 + 1) / 8.0);
}

TEST(SpaceWeatherTable, ApHistoryNeeds57HoursOfTable) {
  const auto t = SpaceWeatherTable::create(60584, numbered_days()).value();
  // Day 2 09:00 (interval 3): 57 h before is day 0 00:00, the table's first interval.
  EXPECT_TRUE(t.ap_history(utc("2024-10-03T09:00:00")).ok());
  const auto early = t.ap_history(utc("2024-10-03T08:59:59"));
  ASSERT_FALSE(early.ok());
  EXPECT_EQ(early.error().field, "t");
}

}  // namespace

