#include "dynamics/space_weather.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>
#include <type_traits>

namespace visors::dynamics {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_csv(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t length = comma == std::string_view::npos ? std::string_view::npos : comma - start;
    fields.push_back(trimmed(line.substr(start, length)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

template <typename T>
std::optional<T> parse(std::string_view text) {
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(value)) return std::nullopt;
  }
  return value;
}

// MJD of 0h UTC of a civil date; an error (field "") for an invalid date.
core::Result<long> utc_day_mjd(int year, int month, int day) {
  core::CalendarTime c;
  c.year = year;
  c.month = month;
  c.day = day;
  const auto start = core::GpsTime::from_calendar(c, core::TimeScale::kUtc);
  if (!start.ok()) return start.error();
  return std::lround(start->jd_utc().mjd());
}

// "YYYY-MM-DD" -> MJD, nullopt when malformed or not a date.
std::optional<long> parse_date(std::string_view text) {
  if (text.size() != 10 || text[4] != '-' || text[7] != '-') return std::nullopt;
  const auto y = parse<int>(text.substr(0, 4));
  const auto m = parse<int>(text.substr(5, 2));
  const auto d = parse<int>(text.substr(8, 2));
  if (!y || !m || !d) return std::nullopt;
  const auto mjd = utc_day_mjd(*y, *m, *d);
  if (!mjd.ok()) return std::nullopt;
  return *mjd;
}

core::Error line_error(std::size_t line_number, std::string message) {
  return core::Error{"line " + std::to_string(line_number), std::move(message)};
}

}  // namespace

core::Result<SpaceWeatherTable> SpaceWeatherTable::load(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return core::Error{"", "cannot open space-weather file '" + path.string() + "'"};

  // Column order of `index` below: DATE, F10.7_OBS, F10.7_OBS_CENTER81, AP_AVG, AP1..AP8.
  constexpr std::array<std::string_view, 12> kColumns{
      "DATE", "F10.7_OBS", "F10.7_OBS_CENTER81", "AP_AVG", "AP1", "AP2",
      "AP3",  "AP4",       "AP5",                "AP6",    "AP7", "AP8"};
  std::array<std::size_t, kColumns.size()> index{};
  std::size_t field_count = 0;
  bool header_seen = false;
  long first_mjd = 0;
  std::vector<Day> days;
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (trimmed(line).empty()) continue;
    const std::vector<std::string_view> fields = split_csv(line);
    if (!header_seen) {
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        const auto it = std::find(fields.begin(), fields.end(), kColumns[c]);
        if (it == fields.end()) {
          return line_error(line_number, "header lacks column '" + std::string(kColumns[c]) + "'");
        }
        index[c] = static_cast<std::size_t>(it - fields.begin());
      }
      field_count = fields.size();
      header_seen = true;
      continue;
    }
    if (fields.size() != field_count) {
      return line_error(line_number, "has " + std::to_string(fields.size()) +
                                         " fields, the header " + std::to_string(field_count));
    }
    const std::string_view date_text = fields[index[0]];
    const auto mjd = parse_date(date_text);
    if (!mjd) {
      return line_error(line_number, "column DATE: '" + std::string(date_text) +
                                         "' is not a date YYYY-MM-DD");
    }
    if (days.empty()) {
      first_mjd = *mjd;
    } else if (*mjd != first_mjd + static_cast<long>(days.size())) {
      return line_error(line_number, "column DATE: " + std::string(date_text) + " does not follow " +
                                         days.back().date + " (rows must be consecutive days)");
    }
    std::array<double, kColumns.size()> value{};
    for (std::size_t c = 1; c < kColumns.size(); ++c) {
      const std::string_view text = fields[index[c]];
      const auto x = parse<double>(text);
      if (!x || *x < 0.0) {
        return line_error(line_number, "column " + std::string(kColumns[c]) + ": '" +
                                           std::string(text) + "' is not a number >= 0");
      }
      value[c] = *x;
    }
    if (!(value[1] > 0.0) || !(value[2] > 0.0)) {
      return line_error(line_number, "column " + std::string(value[1] > 0.0 ? kColumns[2] : kColumns[1]) +
                                         ": F10.7 must be > 0");
    }
    Day day;
    day.date = std::string(date_text);
    day.f107_obs = value[1];
    day.f107_obs_center81 = value[2];
    day.ap_daily = value[3];
    std::copy(value.begin() + 4, value.end(), day.ap.begin());
    days.push_back(std::move(day));
  }
  if (!header_seen) return core::Error{"", "'" + path.string() + "' is empty"};
  if (days.size() < 2) return core::Error{"", "'" + path.string() + "' needs at least 2 days"};
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

}  // namespace visors::dynamics
