#include "visors/core/gps_time.hpp"

#include <erfa.h>

#include <cassert>
#include <cmath>
#include <cstdio>
#include <string>

namespace visors::core {
namespace {

constexpr std::int64_t kNsPerSecond = GpsTime::kNanosecondsPerSecond;
constexpr std::int64_t kSecondsPerDay = 86'400;
constexpr std::int64_t kNsPerDay = kSecondsPerDay * kNsPerSecond;
constexpr std::int64_t kMjd1972 = 41317;  // 1972-01-01: from here on TAI-UTC is a whole number
constexpr std::int64_t kTaiMinusGpsNs = 19 * kNsPerSecond;
constexpr std::int64_t kTtMinusGpsNs = 51'184'000'000;  // 19 s + 32.184 s
constexpr int kMinYear = 1900;
constexpr int kMaxYear = 2200;  // keeps every instant well inside the int64 ns range (+-292 yr)

constexpr std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}
constexpr std::int64_t floor_mod(std::int64_t a, std::int64_t b) { return a - floor_div(a, b) * b; }

// Seconds as a double without forming a huge double first (keeps the sub-second part exact).
double ns_to_seconds(std::int64_t ns) {
  return static_cast<double>(floor_div(ns, kNsPerSecond)) +
         static_cast<double>(floor_mod(ns, kNsPerSecond)) * 1e-9;
}

// Nearest ns to a double number of seconds: split off the whole seconds first, so the rounding
// happens on the fraction only (exact for |s| < 2^52).
std::int64_t seconds_to_ns(double seconds) {
  assert(std::isfinite(seconds) && std::abs(seconds) < 9.2e9);
  const double whole = std::floor(seconds);
  const double fraction = seconds - whole;  // exact, in [0, 1)
  return static_cast<std::int64_t>(whole) * kNsPerSecond + std::llround(fraction * 1e9);
}

struct Civil {
  int year;
  int month;
  int day;
};

Civil civil_from_mjd(std::int64_t mjd) {
  int iy = 0;
  int im = 0;
  int id = 0;
  double fd = 0.0;
  eraJd2cal(2400000.5, static_cast<double>(mjd), &iy, &im, &id, &fd);
  return {iy, im, id};
}

// TAI-UTC [s] for the UTC day `mjd` (ERFA eraDat, whole seconds from 1972 on).
int lookup_tai_minus_utc(std::int64_t mjd) {
  if (mjd < kMjd1972) return 10;
  const Civil c = civil_from_mjd(mjd);
  double dat = 0.0;
  // Status +1 ("dubious year", past the table's horizon) still returns the last known value.
  (void)eraDat(c.year, c.month, c.day, 0.0, &dat);
  return static_cast<int>(std::lround(dat));
}

// The same through a two-day per-thread cache: a conversion needs the day and the next one, and
// successive conversions are almost always on the same day (cuts a GPS->UTC conversion from
// ~200 ns to ~30 ns). A leap-second table changed at run time (eraSetLeapSeconds) is seen on the
// next day change only.
int tai_minus_utc_on_day(std::int64_t mjd) {
  struct Entry {
    std::int64_t mjd = -1;
    int dat = 0;
  };
  thread_local Entry cache[2];
  thread_local unsigned next_slot = 0;
  for (const Entry& e : cache) {
    if (e.mjd == mjd) return e.dat;
  }
  Entry& slot = cache[next_slot];
  next_slot ^= 1U;
  slot = {mjd, lookup_tai_minus_utc(mjd)};
  return slot.dat;
}

// GPS ns at 00:00:00 UTC of UTC day `mjd`.
std::int64_t utc_day_start(std::int64_t mjd) {
  return ((mjd - GpsTime::kGpsEpochMjd) * kSecondsPerDay + tai_minus_utc_on_day(mjd) - 19) *
         kNsPerSecond;
}

struct UtcDay {
  std::int64_t mjd;
  std::int64_t ns_of_day;   // [0, length)
  std::int64_t length_ns;   // 86400 s, or 86401 s on a day that ends with a leap second
  int tai_minus_utc;
};

// The UTC day containing `ns`: the day N with start(N) <= ns < start(N + 1). Starting from the GPS
// day, at most one step is needed (GPS - UTC < 1 day).
UtcDay utc_day_of(std::int64_t ns) {
  std::int64_t mjd = GpsTime::kGpsEpochMjd + floor_div(ns, kNsPerDay);
  std::int64_t start = utc_day_start(mjd);
  while (ns < start) start = utc_day_start(--mjd);
  std::int64_t next = utc_day_start(mjd + 1);
  while (ns >= next) {
    ++mjd;
    start = next;
    next = utc_day_start(mjd + 1);
  }
  return {mjd, ns - start, next - start, tai_minus_utc_on_day(mjd)};
}

// Julian date of a uniform scale given as ns since 1980-01-06 00:00:00 of that scale.
JulianDate uniform_jd(std::int64_t ns_in_scale) {
  const std::int64_t days = floor_div(ns_in_scale, kNsPerDay);
  const std::int64_t rem = floor_mod(ns_in_scale, kNsPerDay);
  return {2400000.5 + static_cast<double>(GpsTime::kGpsEpochMjd + days),
          static_cast<double>(rem) / static_cast<double>(kNsPerDay)};
}

bool is_leap_year(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

int days_in_month(int year, int month) {
  static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month == 2 && is_leap_year(year) ? 29 : kDays[month - 1];
}

std::string two_digits(int v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d", v);
  return buf;
}

Error field_error(std::string field, std::string message) {
  return Error{std::move(field), std::move(message)};
}

}  // namespace

GpsTime GpsTime::from_seconds(double seconds) { return GpsTime(seconds_to_ns(seconds)); }

Result<GpsTime> GpsTime::from_week_seconds(int week, double seconds_of_week) {
  if (week < 0 || week > 15000) {
    return field_error("week", std::to_string(week) + " is outside 0..15000");
  }
  if (!std::isfinite(seconds_of_week) || seconds_of_week < 0.0 ||
      seconds_of_week >= static_cast<double>(kSecondsPerWeek)) {
    return field_error("seconds_of_week", "must be finite and in [0, 604800)");
  }
  return GpsTime(static_cast<std::int64_t>(week) * kNanosecondsPerWeek +
                 seconds_to_ns(seconds_of_week));
}

Result<GpsTime> GpsTime::from_calendar(const CalendarTime& c, TimeScale scale) {
  if (c.year < kMinYear || c.year > kMaxYear) {
    return field_error("year", std::to_string(c.year) + " is outside " +
                                   std::to_string(kMinYear) + ".." + std::to_string(kMaxYear));
  }
  if (c.month < 1 || c.month > 12) {
    return field_error("month", std::to_string(c.month) + " is not a month (1..12)");
  }
  if (c.day < 1 || c.day > days_in_month(c.year, c.month)) {
    return field_error("day", std::to_string(c.day) + " is not a day of " +
                                  std::to_string(c.year) + "-" + two_digits(c.month) + " (1.." +
                                  std::to_string(days_in_month(c.year, c.month)) + ")");
  }
  if (c.hour < 0 || c.hour > 23) {
    return field_error("hour", std::to_string(c.hour) + " is outside 0..23");
  }
  if (c.minute < 0 || c.minute > 59) {
    return field_error("minute", std::to_string(c.minute) + " is outside 0..59");
  }
  if (c.nanosecond < 0 || c.nanosecond >= kNsPerSecond) {
    return field_error("nanosecond", "must be in 0..999999999");
  }
  double djm0 = 0.0;
  double djm = 0.0;
  if (eraCal2jd(c.year, c.month, c.day, &djm0, &djm) != 0) {
    return field_error("day", "not a valid calendar date");  // unreachable after the checks
  }
  const auto mjd = static_cast<std::int64_t>(djm);
  if (scale == TimeScale::kUtc && mjd < kMjd1972) {
    return field_error("year", "UTC before 1972 is not supported (TAI-UTC was not whole seconds)");
  }
  // Second 60 exists only at 23:59 UTC of a day whose end carries a positive leap second.
  const bool leap_day = scale == TimeScale::kUtc &&
                        tai_minus_utc_on_day(mjd + 1) - tai_minus_utc_on_day(mjd) == 1;
  const int max_second = (leap_day && c.hour == 23 && c.minute == 59) ? 60 : 59;
  if (c.second < 0 || c.second > max_second) {
    if (c.second == 60) {
      return field_error("second", scale == TimeScale::kGps
                                       ? "60 does not exist in GPS time (no leap seconds)"
                                       : "60 is valid only at 23:59 UTC of a day that ends with a "
                                         "leap second");
    }
    return field_error("second", std::to_string(c.second) + " is outside 0..59");
  }
  std::int64_t ns = ((mjd - kGpsEpochMjd) * kSecondsPerDay + c.hour * 3600 + c.minute * 60 +
                     c.second) * kNsPerSecond + c.nanosecond;
  if (scale == TimeScale::kUtc) ns += (tai_minus_utc_on_day(mjd) - 19) * kNsPerSecond;
  return GpsTime(ns);
}

Result<GpsTime> GpsTime::parse(std::string_view s, TimeScale scale) {
  const auto syntax_error = [&]() {
    return field_error("", "expected YYYY-MM-DDTHH:MM:SS with an optional .fraction (" +
                               std::string(scale == TimeScale::kUtc ? "UTC" : "GPS") +
                               "), got '" + std::string(s) + "'");
  };
  const auto digit = [&](std::size_t i) { return i < s.size() && s[i] >= '0' && s[i] <= '9'; };
  const auto number = [&](std::size_t at, std::size_t n) {
    int v = 0;
    for (std::size_t i = at; i < at + n; ++i) v = 10 * v + (s[i] - '0');
    return v;
  };
  // Layout: YYYY-MM-DDTHH:MM:SS  (positions of the separators are fixed)
  static constexpr std::string_view kPattern = "dddd-dd-ddTdd:dd:dd";
  if (s.size() < kPattern.size()) return syntax_error();
  for (std::size_t i = 0; i < kPattern.size(); ++i) {
    if (kPattern[i] == 'd' ? !digit(i) : s[i] != kPattern[i]) return syntax_error();
  }
  CalendarTime c;
  c.year = number(0, 4);
  c.month = number(5, 2);
  c.day = number(8, 2);
  c.hour = number(11, 2);
  c.minute = number(14, 2);
  c.second = number(17, 2);
  if (s.size() > kPattern.size()) {
    if (s[kPattern.size()] != '.') return syntax_error();
    const std::size_t first = kPattern.size() + 1;
    std::size_t n = 0;
    while (digit(first + n)) ++n;
    if (n == 0 || first + n != s.size()) return syntax_error();
    if (n > 9) return field_error("second", "more than 9 fractional digits (resolution is 1 ns)");
    std::int64_t frac = 0;
    for (std::size_t i = 0; i < 9; ++i) frac = 10 * frac + (i < n ? s[first + i] - '0' : 0);
    c.nanosecond = frac;
  }
  return from_calendar(c, scale);
}

double GpsTime::seconds() const { return ns_to_seconds(ns_); }

int GpsTime::week() const { return static_cast<int>(floor_div(ns_, kNanosecondsPerWeek)); }

std::int64_t GpsTime::nanoseconds_of_week() const { return floor_mod(ns_, kNanosecondsPerWeek); }

double GpsTime::seconds_of_week() const { return ns_to_seconds(nanoseconds_of_week()); }

CalendarTime GpsTime::calendar(TimeScale scale) const {
  std::int64_t mjd = 0;
  std::int64_t ns_of_day = 0;
  if (scale == TimeScale::kUtc) {
    const UtcDay d = utc_day_of(ns_);
    mjd = d.mjd;
    ns_of_day = d.ns_of_day;
  } else {
    mjd = kGpsEpochMjd + floor_div(ns_, kNsPerDay);
    ns_of_day = floor_mod(ns_, kNsPerDay);
  }
  const Civil civil = civil_from_mjd(mjd);
  CalendarTime c;
  c.year = civil.year;
  c.month = civil.month;
  c.day = civil.day;
  c.nanosecond = ns_of_day % kNsPerSecond;
  const std::int64_t second_of_day = ns_of_day / kNsPerSecond;
  if (second_of_day >= kSecondsPerDay) {  // inside a UTC leap second: 23:59:60
    c.hour = 23;
    c.minute = 59;
    c.second = static_cast<int>(60 + second_of_day - kSecondsPerDay);
  } else {
    c.hour = static_cast<int>(second_of_day / 3600);
    c.minute = static_cast<int>(second_of_day / 60 % 60);
    c.second = static_cast<int>(second_of_day % 60);
  }
  return c;
}

std::string GpsTime::format(TimeScale scale, int decimals) const {
  const CalendarTime c = calendar(scale);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d", c.year, c.month, c.day, c.hour,
                c.minute, c.second);
  std::string text = buf;
  if (decimals > 0) {
    char frac[16];
    std::snprintf(frac, sizeof frac, "%09lld", static_cast<long long>(c.nanosecond));
    text += '.';
    text.append(frac, static_cast<std::size_t>(decimals > 9 ? 9 : decimals));
  }
  return text;
}

int GpsTime::tai_minus_utc() const { return utc_day_of(ns_).tai_minus_utc; }

JulianDate GpsTime::jd_tai() const { return uniform_jd(ns_ + kTaiMinusGpsNs); }

JulianDate GpsTime::jd_tt() const { return uniform_jd(ns_ + kTtMinusGpsNs); }

JulianDate GpsTime::jd_utc() const {
  const UtcDay d = utc_day_of(ns_);
  return {2400000.5 + static_cast<double>(d.mjd),
          static_cast<double>(d.ns_of_day) / static_cast<double>(d.length_ns)};
}

JulianDate GpsTime::jd_ut1(double dut1) const {
  // UT1 - TAI = dut1 - dAT, with dAT of the UTC day in progress (as ERFA's eraUtcut1 does).
  const std::int64_t tai_ns = ns_ + kTaiMinusGpsNs;
  std::int64_t day = floor_div(tai_ns, kNsPerDay);
  const double seconds_of_day =
      static_cast<double>(floor_mod(tai_ns, kNsPerDay)) * 1e-9 + (dut1 - tai_minus_utc());
  double fraction = seconds_of_day / static_cast<double>(kSecondsPerDay);
  const double whole = std::floor(fraction);
  day += static_cast<std::int64_t>(whole);
  fraction -= whole;
  return {2400000.5 + static_cast<double>(kGpsEpochMjd + day), fraction};
}

GpsTime GpsTime::operator+(double seconds) const { return GpsTime(ns_ + seconds_to_ns(seconds)); }

double GpsTime::seconds_since(GpsTime earlier) const { return ns_to_seconds(ns_ - earlier.ns_); }

}  // namespace visors::core
