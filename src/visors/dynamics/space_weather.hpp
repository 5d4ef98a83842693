#pragma once
// Daily space weather (F10.7, Ap, 3-hourly ap), as read on the ground from a CelesTrak CSV file
// (dynamics/files/space_weather_file.hpp), e.g.
// data/space_weather/SW-Observed_2024-07-01_2025-01-31.csv.
//
// at(t) follows the NRLMSISE-00 input convention (Picone et al. 2002;
// docs/nrlmsise00.md#conventions):
//   f107  = observed F10.7 of the PREVIOUS UTC day (the flux lags the thermosphere by ~1 day),
//   f107a = F10.7_OBS_CENTER81: 81-day mean of the observed flux centred on the current day,
//   ap    = daily Ap (AP_AVG) of the current day.
// Units: F10.7 in sfu (1e-22 W m^-2 Hz^-1), ap and Ap in units of 2 nT. F10.7 is taken as it
// stands for the whole UTC day (the measurement is at 20 UT at Penticton; not interpolated).

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/dynamics/atmosphere.hpp"

namespace visors::dynamics {

class SpaceWeatherTable {
 public:
  /// The values of one UTC day.
  struct Day {
    std::string date;                // "YYYY-MM-DD" (for messages)
    double f107_obs = 0.0;           // observed F10.7 [sfu]
    double f107_obs_center81 = 0.0;  // 81-day mean of the observed F10.7, centred [sfu]
    double ap_daily = 0.0;           // daily Ap [2 nT]
    std::array<double, 8> ap{};      // 3-hourly ap, AP1 = 00-03 UTC .. AP8 = 21-24 UTC [2 nT]
  };

  /// The table of `days`, consecutive UTC days from `first_mjd` (UTC MJD of days[0]): at least 2
  /// days, F10.7 finite and > 0, ap finite and >= 0. Errors name "days" or "days[k]".
  static core::Result<SpaceWeatherTable> create(long first_mjd, std::vector<Day> days);

  /// Activity at `t` (NRLMSISE-00 convention above). Valid from the table's second day (f107
  /// needs the previous day) to the end of its last day; outside, an error naming that range.
  [[nodiscard]] core::Result<SolarActivity> at(core::GpsTime t) const;

  /// 3-hourly ap of the interval holding `t` (AP1 = 00-03 UTC, ..., AP8 = 21-24 UTC) [2 nT].
  /// Valid over every day of the table.
  [[nodiscard]] core::Result<double> ap_3hourly(core::GpsTime t) const;

  /// The NRLMSISE-00 ap array at `t` (Picone et al. 2002; the model's documentation of its ap
  /// input): [0] daily Ap of t's UTC day, [1] ap_3hourly(t), [2..4] ap_3hourly(t - 3, 6, 9 h),
  /// [5] the mean of ap_3hourly(t - 12 h, t - 15 h, ..., t - 33 h), [6] the mean of
  /// ap_3hourly(t - 36 h, ..., t - 57 h). Needs the table from 57 h before t's interval: valid
  /// from the third day's 09:00 UTC; before, an error naming "t".
  [[nodiscard]] core::Result<std::array<double, 7>> ap_history(core::GpsTime t) const;

  [[nodiscard]] std::size_t size() const { return days_.size(); }
  [[nodiscard]] long first_mjd() const { return first_mjd_; }  // UTC day [d]
  [[nodiscard]] long last_mjd() const { return first_mjd_ + static_cast<long>(days_.size()) - 1; }

 private:
  SpaceWeatherTable(long first_mjd, std::vector<Day> days)
      : first_mjd_(first_mjd), days_(std::move(days)) {}
  // Index of t's UTC day in days_, or an error naming the valid range starting at `first`.
  [[nodiscard]] core::Result<std::size_t> day_index(core::GpsTime t, std::size_t first) const;

  long first_mjd_ = 0;
  std::vector<Day> days_;
};

/// MJD of 0h UTC of a civil date; an error (field "") for an invalid date.
core::Result<long> utc_day_mjd(int year, int month, int day);

}  // namespace visors::dynamics
