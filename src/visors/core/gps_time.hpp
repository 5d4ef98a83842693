#pragma once
// GpsTime: the project's internal time (docs/conventions.md "Time"): integer nanoseconds since the
// GPS epoch 1980-01-06 00:00:00 GPST. Integer storage means no floating drift: adding 1 s a million
// times is exact. Other scales are derived at the edges:
//   TAI = GPST + 19 s, TT = TAI + 32.184 s (exact, IERS Conventions 2010 ch. 10);
//   UTC = TAI - dAT, dAT from ERFA eraDat (its compiled-in leap-second table) for the UTC date;
//   UT1 = UTC + (UT1-UTC), UT1-UTC from the EOP (core/eop.hpp).
// A UTC leap second (23:59:60.x) is representable: conversions from UTC accept second 60 on a day
// that ends with a positive leap second, and calendar(kUtc) returns it.
// UTC conversions use integer dAT and are valid from 1972-01-01; earlier dates use dAT = 10 s.

#include <chrono>
#include <compare>
#include <cstdint>
#include <string>
#include <string_view>

#include "visors/core/result.hpp"

namespace visors::core {

enum class TimeScale { kGps, kUtc };

/// Broken-down civil time in one scale. `second` is 60 only inside a UTC leap second.
struct CalendarTime {
  int year = 1980;
  int month = 1;
  int day = 6;
  int hour = 0;
  int minute = 0;
  int second = 0;
  std::int64_t nanosecond = 0;  // [0, 1e9)
  friend bool operator==(const CalendarTime&, const CalendarTime&) = default;
};

/// Two-part Julian date for ERFA: jd1 = 2400000.5 + whole MJD days, jd2 = fraction of day in
/// [0, 1). Keeping the fraction separate resolves ~2e-11 s, and is the split ERFA recommends for
/// eraEra00 (the "date & time method"); a single double JD near 2.46e6 d resolves only ~40 us.
struct JulianDate {
  double jd1 = 2400000.5;
  double jd2 = 0.0;
  [[nodiscard]] double mjd() const { return (jd1 - 2400000.5) + jd2; }  // [d], rounded
};

class GpsTime {
 public:
  static constexpr std::int64_t kNanosecondsPerSecond = 1'000'000'000;
  static constexpr std::int64_t kSecondsPerWeek = 604'800;
  static constexpr std::int64_t kNanosecondsPerWeek = kSecondsPerWeek * kNanosecondsPerSecond;
  static constexpr double kTaiMinusGps = 19.0;  // [s], exact
  static constexpr double kTtMinusTai = 32.184;  // [s], exact
  static constexpr std::int64_t kGpsEpochMjd = 44244;  // 1980-01-06

  constexpr GpsTime() = default;  // the GPS epoch

  static constexpr GpsTime from_nanoseconds(std::int64_t ns) { return GpsTime(ns); }
  /// Seconds since the GPS epoch, rounded to the nearest ns. Precondition: finite, |s| < 9.2e9.
  static GpsTime from_seconds(double seconds);
  /// GPS week (full, not modulo 1024) and seconds of week in [0, 604800).
  static Result<GpsTime> from_week_seconds(int week, double seconds_of_week);
  /// Civil date-time in the given scale; every field is validated.
  static Result<GpsTime> from_calendar(const CalendarTime& calendar, TimeScale scale);
  /// Parses "YYYY-MM-DDTHH:MM:SS" with an optional fraction of 1..9 digits, in `scale`.
  static Result<GpsTime> parse(std::string_view iso, TimeScale scale);

  [[nodiscard]] constexpr std::int64_t nanoseconds() const { return ns_; }
  [[nodiscard]] double seconds() const;  // since the GPS epoch [s] (double: ~0.2 us resolution)
  [[nodiscard]] int week() const;        // floor(t / 1 week)
  [[nodiscard]] double seconds_of_week() const;  // [s] in [0, 604800)
  [[nodiscard]] std::int64_t nanoseconds_of_week() const;

  [[nodiscard]] CalendarTime calendar(TimeScale scale) const;
  /// ISO form of calendar(scale); the fraction is truncated to `decimals` digits (0..9) so the
  /// text never rounds into the next second.
  [[nodiscard]] std::string format(TimeScale scale, int decimals = 3) const;

  [[nodiscard]] int tai_minus_utc() const;  // dAT [s] in effect at this instant
  [[nodiscard]] int gps_minus_utc() const { return tai_minus_utc() - 19; }  // [s]

  [[nodiscard]] JulianDate jd_tai() const;
  [[nodiscard]] JulianDate jd_tt() const;
  /// ERFA's quasi-JD for UTC: on a day ending in a leap second the fraction is seconds/86401, so
  /// the result is what eraDtf2d returns and can be passed to eraUtctai/eraUtcut1.
  [[nodiscard]] JulianDate jd_utc() const;
  /// UT1 = UTC + dut1 [s], formed as TAI + (dut1 - dAT) so it is continuous across a leap second.
  [[nodiscard]] JulianDate jd_ut1(double dut1) const;

  [[nodiscard]] GpsTime operator+(double seconds) const;  // rounded to the nearest ns
  [[nodiscard]] GpsTime operator-(double seconds) const { return *this + (-seconds); }
  [[nodiscard]] constexpr GpsTime operator+(std::chrono::nanoseconds dt) const {
    return GpsTime(ns_ + dt.count());
  }
  [[nodiscard]] constexpr GpsTime operator-(std::chrono::nanoseconds dt) const {
    return GpsTime(ns_ - dt.count());
  }
  GpsTime& operator+=(double seconds) { return *this = *this + seconds; }
  GpsTime& operator+=(std::chrono::nanoseconds dt) { return *this = *this + dt; }

  /// this - earlier, exactly in ns / in seconds as a double.
  [[nodiscard]] constexpr std::int64_t nanoseconds_since(GpsTime earlier) const {
    return ns_ - earlier.ns_;
  }
  [[nodiscard]] double seconds_since(GpsTime earlier) const;

  friend constexpr auto operator<=>(GpsTime, GpsTime) = default;

 private:
  constexpr explicit GpsTime(std::int64_t ns) : ns_(ns) {}
  std::int64_t ns_ = 0;
};

}  // namespace visors::core
