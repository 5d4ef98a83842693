#pragma once
// Daily space weather (F10.7, Ap, 3-hourly ap) from a CelesTrak CSV file (the SW-All.csv layout,
// https://celestrak.org/SpaceData/SpaceWx-format.php), e.g.
// shared/data/space_weather/SW-Observed_2024-07-01_2025-01-31.csv.
//
// Columns are found by their header names (DATE, F10.7_OBS, F10.7_OBS_CENTER81, AP_AVG,
// AP1..AP8); others are ignored. Rows must be consecutive UTC days with every used field filled:
// only observed data are accepted (trim CelesTrak's predicted blocks, whose ap fields are blank).
//
// at(t) follows the NRLMSISE-00 input convention (Picone et al. 2002; SOURCES.md sec. 2):
//   f107  = observed F10.7 of the PREVIOUS UTC day (the flux lags the thermosphere by ~1 day),
//   f107a = F10.7_OBS_CENTER81: 81-day mean of the observed flux centred on the current day,
//   ap    = daily Ap (AP_AVG) of the current day.
// Units: F10.7 in sfu (1e-22 W m^-2 Hz^-1), ap and Ap in units of 2 nT. F10.7 is taken as it
// stands for the whole UTC day (the measurement is at 20 UT at Penticton; not interpolated).

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/gps_time.hpp"
#include "core/status.hpp"
#include "dynamics/atmosphere.hpp"

namespace visors::dynamics {

class SpaceWeatherTable {
 public:
  /// Parses the CSV. Errors name the line ("line N") and the column (by header name).
  static core::Result<SpaceWeatherTable> load(const std::filesystem::path& path);

  /// Activity at `t` (NRLMSISE-00 convention above). Valid from the table's second day (f107
  /// needs the previous day) to the end of its last day; outside, an error naming that range.
  [[nodiscard]] core::Result<SolarActivity> at(core::GpsTime t) const;

  /// 3-hourly ap of the interval holding `t` (AP1 = 00-03 UTC, ..., AP8 = 21-24 UTC) [2 nT].
  /// Valid over every day of the table.
  [[nodiscard]] core::Result<double> ap_3hourly(core::GpsTime t) const;

  [[nodiscard]] std::size_t size() const { return days_.size(); }
  [[nodiscard]] long first_mjd() const { return first_mjd_; }  // UTC day [d]
  [[nodiscard]] long last_mjd() const { return first_mjd_ + static_cast<long>(days_.size()) - 1; }

 private:
  struct Day {
    std::string date;                // "YYYY-MM-DD" as in the file (for messages)
    double f107_obs = 0.0;           // [sfu]
    double f107_obs_center81 = 0.0;  // [sfu]
    double ap_daily = 0.0;           // [2 nT]
    std::array<double, 8> ap{};      // 3-hourly [2 nT]
  };
  SpaceWeatherTable(long first_mjd, std::vector<Day> days)
      : first_mjd_(first_mjd), days_(std::move(days)) {}
  // Index of t's UTC day in days_, or an error naming the valid range starting at `first`.
  [[nodiscard]] core::Result<std::size_t> day_index(core::GpsTime t, std::size_t first) const;

  long first_mjd_ = 0;
  std::vector<Day> days_;
};

}  // namespace visors::dynamics
