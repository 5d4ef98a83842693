#include "visors/dynamics/space_weather.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace visors::dynamics {
namespace {

bool positive(double x) { return std::isfinite(x) && x > 0.0; }
bool non_negative(double x) { return std::isfinite(x) && x >= 0.0; }

}  // namespace

core::Result<long> utc_day_mjd(int year, int month, int day) {
  core::CalendarTime c;
  c.year = year;
  c.month = month;
  c.day = day;
  const auto start = core::GpsTime::from_calendar(c, core::TimeScale::kUtc);
  if (!start.ok()) return start.error();
  return std::lround(start->jd_utc().mjd());
}

core::Result<SpaceWeatherTable> SpaceWeatherTable::create(long first_mjd, std::vector<Day> days) {
  if (days.size() < 2) return core::Error{"days", "needs at least 2 days"};
  for (std::size_t k = 0; k < days.size(); ++k) {
    const Day& d = days[k];
    const std::string field = "days[" + std::to_string(k) + "]";
    if (!positive(d.f107_obs) || !positive(d.f107_obs_center81)) {
      return core::Error{field, "F10.7 must be finite and > 0"};
    }
    if (!non_negative(d.ap_daily) || !std::all_of(d.ap.begin(), d.ap.end(), non_negative)) {
      return core::Error{field, "ap must be finite and >= 0"};
    }
  }
  return SpaceWeatherTable(first_mjd, std::move(days));
}

core::Result<std::size_t> SpaceWeatherTable::day_index(core::GpsTime t, std::size_t first) const {
  const core::CalendarTime c = t.calendar(core::TimeScale::kUtc);
  const auto mjd = utc_day_mjd(c.year, c.month, c.day);
  const long offset = mjd.ok() ? *mjd - first_mjd_ : -1;
  if (offset < static_cast<long>(first) || offset >= static_cast<long>(days_.size())) {
    return core::Error{"t", t.format(core::TimeScale::kUtc, 0) + " UTC is outside the space-weather range " +
                                days_[first].date + "T00:00:00 .. " + days_.back().date +
                                "T24:00:00 UTC"};
  }
  return static_cast<std::size_t>(offset);
}

core::Result<SolarActivity> SpaceWeatherTable::at(core::GpsTime t) const {
  // From the second day: f107 is the previous day's value.
  const auto i = day_index(t, 1);
  if (!i.ok()) return i.error();
  SolarActivity a;
  a.f107 = days_[*i - 1].f107_obs;
  a.f107a = days_[*i].f107_obs_center81;
  a.ap = days_[*i].ap_daily;
  return a;
}

core::Result<double> SpaceWeatherTable::ap_3hourly(core::GpsTime t) const {
  const auto i = day_index(t, 0);
  if (!i.ok()) return i.error();
  // Interval hour / 3; a leap second (23:59:60) belongs to the last interval.
  const int hour = t.calendar(core::TimeScale::kUtc).hour;
  return days_[*i].ap[static_cast<std::size_t>(std::clamp(hour / 3, 0, 7))];
}

core::Result<std::array<double, 7>> SpaceWeatherTable::ap_history(core::GpsTime t) const {
  const auto day = day_index(t, 0);
  if (!day.ok()) return day.error();
  // The 3-hourly value k intervals (3 h each) before t's.
  auto ap_before = [&](int k) { return ap_3hourly(t - 10800.0 * k); };
  std::array<double, 7> ap{};
  ap[0] = days_[*day].ap_daily;
  for (int k = 0; k < 4; ++k) {
    const auto v = ap_before(k);
    if (!v.ok()) return v.error();
    ap[static_cast<std::size_t>(k) + 1] = *v;
  }
  // Means of the eight values 12-33 h and 36-57 h before (intervals 4-11 and 12-19 back).
  for (int block = 0; block < 2; ++block) {
    double sum = 0.0;
    for (int k = 4 + 8 * block; k < 12 + 8 * block; ++k) {
      const auto v = ap_before(k);
      if (!v.ok()) return core::Error{"t", "the ap history of " + t.format(core::TimeScale::kUtc, 0) +
                                               " UTC reaches before the space-weather table (" + v.error().message + ")"};
      sum += *v;
    }
    ap[static_cast<std::size_t>(5 + block)] = sum / 8.0;
  }
  return ap;
}

}  // namespace visors::dynamics
