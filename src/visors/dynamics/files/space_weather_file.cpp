#include "visors/dynamics/files/space_weather_file.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "visors/core/files/csv_file.hpp"

namespace visors::dynamics::files {
namespace {

std::optional<int> parse_int(std::string_view text) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}


// "YYYY-MM-DD" -> MJD, nullopt when malformed or not a date.
std::optional<long> parse_date(std::string_view text) {
  if (text.size() != 10 || text[4] != '-' || text[7] != '-') return std::nullopt;
  const auto y = parse_int(text.substr(0, 4));
  const auto m = parse_int(text.substr(5, 2));
  const auto d = parse_int(text.substr(8, 2));
  if (!y || !m || !d) return std::nullopt;
  const auto mjd = utc_day_mjd(*y, *m, *d);
  if (!mjd.ok()) return std::nullopt;
  return *mjd;
}

}  // namespace

core::Result<SpaceWeatherTable> read_space_weather_file(const std::filesystem::path& path) {
  // Column order: DATE, F10.7_OBS, F10.7_OBS_CENTER81, AP_AVG, AP1..AP8.
  constexpr std::array<std::string_view, 12> kColumns{
      "DATE", "F10.7_OBS", "F10.7_OBS_CENTER81", "AP_AVG", "AP1", "AP2",
      "AP3",  "AP4",       "AP5",                "AP6",    "AP7", "AP8"};
  const auto rows = core::files::read_csv_columns(path, kColumns, "space-weather file");
  if (!rows.ok()) return rows.error();
  long first_mjd = 0;
  std::vector<SpaceWeatherTable::Day> days;
  for (const core::files::CsvRow& row : rows.value()) {
    const std::string& date_text = row.fields[0];
    const auto mjd = parse_date(date_text);
    if (!mjd) return core::files::line_error(row.line, "column DATE: '" + date_text + "' is not a date YYYY-MM-DD");
    if (days.empty()) {
      first_mjd = *mjd;
    } else if (*mjd != first_mjd + static_cast<long>(days.size())) {
      return core::files::line_error(row.line, "column DATE: " + date_text + " does not follow " + days.back().date +
                                            " (rows must be consecutive days)");
    }
    std::array<double, kColumns.size()> value{};
    for (std::size_t c = 1; c < kColumns.size(); ++c) {
      const auto x = core::files::parse_finite_number(row.fields[c]);
      if (!x || *x < 0.0) {
        return core::files::line_error(row.line, "column " + std::string(kColumns[c]) + ": '" + row.fields[c] +
                                              "' is not a number >= 0");
      }
      value[c] = *x;
    }
    if (!(value[1] > 0.0) || !(value[2] > 0.0)) {
      return core::files::line_error(row.line, "column " + std::string(value[1] > 0.0 ? kColumns[2] : kColumns[1]) +
                                            ": F10.7 must be > 0");
    }
    SpaceWeatherTable::Day day;
    day.date = date_text;
    day.f107_obs = value[1];
    day.f107_obs_center81 = value[2];
    day.ap_daily = value[3];
    std::copy(value.begin() + 4, value.end(), day.ap.begin());
    days.push_back(std::move(day));
  }
  if (days.size() < 2) return core::Error{"", "space-weather file '" + path.string() + "' needs at least 2 days"};
  return SpaceWeatherTable::create(first_mjd, std::move(days));  // the checks above leave nothing for it to reject
}

}  // namespace visors::dynamics::files
