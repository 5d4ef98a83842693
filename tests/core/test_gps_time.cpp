// GpsTime: scales, week/TOW, calendar, leap seconds, ISO strings, exact arithmetic.
#include <gtest/gtest.h>

#include <erfa.h>

#include <chrono>
#include <string>

#include "visors/core/gps_time.hpp"

namespace {

using visors::core::CalendarTime;
using visors::core::GpsTime;
using visors::core::JulianDate;
using visors::core::TimeScale;

GpsTime gps(const std::string& iso) {
  auto t = GpsTime::parse(iso, TimeScale::kGps);
  EXPECT_TRUE(t.ok()) << iso << ": " << (t.ok() ? "" : t.error().describe());
  return t.ok() ? *t : GpsTime{};
}

GpsTime utc(const std::string& iso) {
  auto t = GpsTime::parse(iso, TimeScale::kUtc);
  EXPECT_TRUE(t.ok()) << iso << ": " << (t.ok() ? "" : t.error().describe());
  return t.ok() ? *t : GpsTime{};
}

// (a - b) in seconds for two-part Julian dates.
double jd_difference_s(const JulianDate& a, const JulianDate& b) {
  return ((a.jd1 - b.jd1) + (a.jd2 - b.jd2)) * 86400.0;
}

TEST(GpsTime, ErfaLeapSecondTableValues) {
  // ERFA src/t_erfa_c.c, t_dat: eraDat(2003,6,1) = 32, (2008,1,17) = 33, (2017,9,1) = 37 s.
  double dat = 0.0;
  ASSERT_EQ(eraDat(2003, 6, 1, 0.0, &dat), 0);
  EXPECT_EQ(dat, 32.0);
  ASSERT_EQ(eraDat(2008, 1, 17, 0.0, &dat), 0);
  EXPECT_EQ(dat, 33.0);
  ASSERT_EQ(eraDat(2017, 9, 1, 0.0, &dat), 0);
  EXPECT_EQ(dat, 37.0);
  // The same through GpsTime.
  EXPECT_EQ(utc("2003-06-01T00:00:00").tai_minus_utc(), 32);
  EXPECT_EQ(utc("2008-01-17T00:00:00").tai_minus_utc(), 33);
  EXPECT_EQ(utc("2017-09-01T00:00:00").tai_minus_utc(), 37);
}

TEST(GpsTime, EpochIsWeekZero) {
  const GpsTime t0 = gps("1980-01-06T00:00:00");
  EXPECT_EQ(t0.nanoseconds(), 0);
  EXPECT_EQ(t0.week(), 0);
  // GPS time was set equal to UTC at its epoch (TAI - UTC = 19 s in 1980).
  EXPECT_EQ(t0, utc("1980-01-06T00:00:00"));
}

TEST(GpsTime, MissionEpoch) {
  // 2024-10-01 00:00:00 GPST: week 2334, TOW 172800 s (Tuesday); GPS - UTC = 18 s, so UTC is
  // 2024-09-30T23:59:42 and TT - UTC = 18 + 51.184 = 69.184 s (worked example in
  // docs/algorithms/dynamics.md#time-scales).
  const GpsTime t = gps("2024-10-01T00:00:00");
  EXPECT_EQ(t.week(), 2334);
  EXPECT_EQ(t.seconds_of_week(), 172800.0);
  EXPECT_EQ(t.gps_minus_utc(), 18);
  EXPECT_EQ(t.format(TimeScale::kUtc, 0), "2024-09-30T23:59:42");
  // definitions TT - TAI = 32.184 s, TAI - UTC = 37 s (exact). Loose: measured 2.4e-12 s (2026-11), bound 1e-6 ~4e5x above round-off
  EXPECT_NEAR(jd_difference_s(t.jd_tt(), t.jd_utc()), 69.184, 1e-6);
  EXPECT_NEAR(jd_difference_s(t.jd_tt(), t.jd_tai()), 32.184, 1e-6);
  const auto w = GpsTime::from_week_seconds(2334, 172800.0);
  ASSERT_TRUE(w.ok());
  EXPECT_EQ(*w, t);
}

TEST(GpsTime, BroadcastEphemerisEpoch2010) {
  // t_oe of G01 in brdc1820.10n: 2010-07-01 12:00:00 GPST = week 1590, TOW 388800 s.
  const GpsTime t = gps("2010-07-01T12:00:00");
  EXPECT_EQ(t.week(), 1590);
  EXPECT_EQ(t.seconds_of_week(), 388800.0);
  EXPECT_EQ(t.week() % 1024, 566);  // the LNAV 10-bit week field
}

TEST(GpsTime, TerrestrialTimeOfJ2000IsExact) {
  // J2000.0 = 2000-01-01 12:00:00 TT = 11:59:08.816 GPST (TT - GPST = 51.184 s exactly).
  const GpsTime t = gps("2000-01-01T11:59:08.816");
  const JulianDate tt = t.jd_tt();
  EXPECT_EQ(tt.jd1 + tt.jd2, 2451545.0);
  EXPECT_EQ(tt.jd2, 0.5);
}

TEST(GpsTime, UtcJulianDateAgreesWithErfa) {
  for (const char* iso : {"2004-04-06T07:51:28.386009", "2016-12-31T23:59:60.25",
                          "2024-10-01T00:00:00"}) {
    const GpsTime t = utc(iso);
    // ERFA's own quasi-JD for the same UTC, then TAI from it.
    const JulianDate ours = t.jd_utc();
    double tai1 = 0.0;
    double tai2 = 0.0;
    ASSERT_EQ(eraUtctai(ours.jd1, ours.jd2, &tai1, &tai2), 0) << iso;
    // ERFA eraUtctai / eraUtcut1 (independent); round-off of a two-part JD ~1e-11 s: measured 1.9e-11 s (TAI), 1.0e-15 s (UT1) (2026-11); bound 1e-9 (UT1: loose, ~1e6x)
    EXPECT_NEAR(jd_difference_s(JulianDate{tai1, tai2}, t.jd_tai()), 0.0, 1e-9) << iso;
    double ut11 = 0.0;
    double ut12 = 0.0;
    ASSERT_EQ(eraUtcut1(ours.jd1, ours.jd2, 0.3, &ut11, &ut12), 0) << iso;
    EXPECT_NEAR(jd_difference_s(JulianDate{ut11, ut12}, t.jd_ut1(0.3)), 0.0, 1e-9) << iso;
  }
}

TEST(GpsTime, LeapSecondEndOf2016) {
  // A leap second was inserted at the end of 2016-12-31: TAI - UTC 36 -> 37 s, GPS - UTC 17 -> 18.
  const GpsTime before = utc("2016-12-31T23:59:59");
  const GpsTime leap = utc("2016-12-31T23:59:60");
  const GpsTime after = utc("2017-01-01T00:00:00");
  EXPECT_EQ(before.gps_minus_utc(), 17);
  EXPECT_EQ(leap.gps_minus_utc(), 17);
  EXPECT_EQ(after.gps_minus_utc(), 18);
  // 23:59:60 is a real, unique second between the two.
  EXPECT_EQ(leap.nanoseconds_since(before), 1'000'000'000);
  EXPECT_EQ(after.nanoseconds_since(leap), 1'000'000'000);
  EXPECT_EQ(before.format(TimeScale::kGps, 0), "2017-01-01T00:00:16");
  EXPECT_EQ(leap.format(TimeScale::kGps, 0), "2017-01-01T00:00:17");
  EXPECT_EQ(after.format(TimeScale::kGps, 0), "2017-01-01T00:00:18");
  // Round trip UTC -> GPS -> UTC every quarter second across the leap.
  const GpsTime start = utc("2016-12-31T23:59:58");
  const char* expected[] = {"2016-12-31T23:59:58.000", "2016-12-31T23:59:58.250",
                            "2016-12-31T23:59:58.500", "2016-12-31T23:59:58.750",
                            "2016-12-31T23:59:59.000", "2016-12-31T23:59:59.250",
                            "2016-12-31T23:59:59.500", "2016-12-31T23:59:59.750",
                            "2016-12-31T23:59:60.000", "2016-12-31T23:59:60.250",
                            "2016-12-31T23:59:60.500", "2016-12-31T23:59:60.750",
                            "2017-01-01T00:00:00.000", "2017-01-01T00:00:00.250",
                            "2017-01-01T00:00:00.500", "2017-01-01T00:00:00.750",
                            "2017-01-01T00:00:01.000"};
  for (int k = 0; k < 17; ++k) {
    const GpsTime t = start + 0.25 * k;
    const std::string text = t.format(TimeScale::kUtc, 3);
    EXPECT_EQ(text, expected[k]);
    EXPECT_EQ(utc(text), t) << text;
  }
  const CalendarTime c = leap.calendar(TimeScale::kUtc);
  EXPECT_EQ(c.second, 60);
  EXPECT_EQ(c.minute, 59);
  EXPECT_EQ(c.day, 31);
}

TEST(GpsTime, SecondSixtyOnlyInALeapSecond) {
  const auto normal_day = GpsTime::parse("2017-12-31T23:59:60", TimeScale::kUtc);
  ASSERT_FALSE(normal_day.ok());
  EXPECT_EQ(normal_day.error().field, "second");
  const auto gps_scale = GpsTime::parse("2016-12-31T23:59:60", TimeScale::kGps);
  ASSERT_FALSE(gps_scale.ok());
  EXPECT_EQ(gps_scale.error().field, "second");
  const auto wrong_minute = GpsTime::parse("2016-12-31T23:58:60", TimeScale::kUtc);
  EXPECT_FALSE(wrong_minute.ok());
}

TEST(GpsTime, WeekRollovers) {
  // The 10-bit LNAV week rolled over at 1999-08-22 00:00 GPST (week 1024) and at 2019-04-07
  // 00:00 GPST (week 2048) = 2019-04-06 23:59:42 UTC.
  EXPECT_EQ(gps("1999-08-22T00:00:00").week(), 1024);
  const GpsTime r2 = gps("2019-04-07T00:00:00");
  EXPECT_EQ(r2.week(), 2048);
  EXPECT_EQ(r2.seconds_of_week(), 0.0);
  EXPECT_EQ(r2, utc("2019-04-06T23:59:42"));
  // Crossing a week boundary by arithmetic.
  const auto t = GpsTime::from_week_seconds(2333, 604799.5);
  ASSERT_TRUE(t.ok());
  const GpsTime u = *t + 1.0;
  EXPECT_EQ(u.week(), 2334);
  EXPECT_EQ(u.seconds_of_week(), 0.5);
  EXPECT_EQ((u - 1.0).week(), 2333);
  EXPECT_FALSE(GpsTime::from_week_seconds(2333, 604800.0).ok());
  EXPECT_FALSE(GpsTime::from_week_seconds(2333, -1e-9).ok());
  EXPECT_FALSE(GpsTime::from_week_seconds(-1, 0.0).ok());
}

TEST(GpsTime, RepeatedAdditionIsExact) {
  const GpsTime t0 = gps("2024-10-01T00:00:00");
  GpsTime a = t0;
  GpsTime b = t0;
  GpsTime c = t0;
  for (int k = 0; k < 1'000'000; ++k) {
    a += 1.0;
    b += 0.1;  // 0.1 is not a binary fraction, but it rounds to exactly 100000000 ns
    c += std::chrono::nanoseconds(7);
  }
  EXPECT_EQ(a.nanoseconds_since(t0), 1'000'000LL * 1'000'000'000LL);
  EXPECT_EQ(b.nanoseconds_since(t0), 100'000LL * 1'000'000'000LL);
  EXPECT_EQ(c.nanoseconds_since(t0), 7'000'000LL);
  EXPECT_EQ(a.seconds_since(t0), 1e6);
}

TEST(GpsTime, ArithmeticAndComparison) {
  const GpsTime t = gps("2024-10-01T00:00:00");
  EXPECT_EQ((t + 1.5e-9).nanoseconds_since(t), 2);  // rounded to the nearest ns
  EXPECT_EQ((t + 1.4e-9).nanoseconds_since(t), 1);
  EXPECT_EQ((t - 0.25).nanoseconds_since(t), -250'000'000);
  EXPECT_LT(t, t + 1e-9);
  EXPECT_GT(t, t - std::chrono::nanoseconds(1));
  EXPECT_DOUBLE_EQ((t + 3600.0).seconds_since(t), 3600.0);
  EXPECT_EQ(GpsTime::from_seconds(t.seconds()), t);  // whole seconds are exact in a double
  EXPECT_EQ(GpsTime::from_seconds(12.000000001).nanoseconds(), 12'000'000'001);
  EXPECT_EQ(GpsTime::from_nanoseconds(-1).week(), -1);
}

TEST(GpsTime, CalendarRoundTripInBothScales) {
  const GpsTime t = gps("2024-02-29T13:14:15.123456789");
  const CalendarTime c = t.calendar(TimeScale::kGps);
  EXPECT_EQ(c, (CalendarTime{2024, 2, 29, 13, 14, 15, 123456789}));
  EXPECT_EQ(t.format(TimeScale::kGps, 9), "2024-02-29T13:14:15.123456789");
  EXPECT_EQ(t.format(TimeScale::kGps, 2), "2024-02-29T13:14:15.12");  // truncated, not rounded
  EXPECT_EQ(t.format(TimeScale::kUtc, 3), "2024-02-29T13:13:57.123");
  const auto back = GpsTime::from_calendar(t.calendar(TimeScale::kUtc), TimeScale::kUtc);
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(*back, t);
}

TEST(GpsTime, BadStringsAreRejectedWithTheProblemNamed) {
  struct Case {
    const char* text;
    const char* field;
    const char* says;
  };
  const Case cases[] = {
      {"2024-13-01T00:00:00", "month", "13 is not a month"},
      {"2024-00-01T00:00:00", "month", "0 is not a month"},
      {"2023-02-29T00:00:00", "day", "29 is not a day of 2023-02"},
      {"2024-04-31T00:00:00", "day", "31 is not a day"},
      {"2024-01-01T24:00:00", "hour", "24"},
      {"2024-01-01T00:60:00", "minute", "60"},
      {"2024-01-01T00:00:61", "second", "61"},
      {"2024-01-01T00:00:00.1234567891", "second", "9 fractional digits"},
      {"2024-1-01T00:00:00", "", "expected YYYY-MM-DDTHH:MM:SS"},
      {"2024-01-01 00:00:00", "", "expected"},
      {"2024-01-01T00:00:00Z", "", "expected"},
      {"2024-01-01T00:00:00.", "", "expected"},
      {"", "", "expected"},
      {"1850-01-01T00:00:00", "year", "outside"},
  };
  for (const auto& c : cases) {
    const auto r = GpsTime::parse(c.text, TimeScale::kUtc);
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().field, c.field) << c.text;
    EXPECT_NE(r.error().message.find(c.says), std::string::npos)
        << c.text << " -> " << r.error().describe();
  }
  // A fraction of 1..9 digits is accepted.
  EXPECT_EQ(utc("2024-01-01T00:00:00.5").calendar(TimeScale::kUtc).nanosecond, 500'000'000);
  EXPECT_FALSE(GpsTime::parse("1971-12-31T00:00:00", TimeScale::kUtc).ok());  // before 1972
}

}  // namespace
