#pragma once
// Earth orientation parameters (EOP): a table of daily values at 0h UTC (the IERS finals2000A
// Bulletin A columns, read on the ground by core/files/eop_file.hpp), interpolated linearly in UTC
// MJD. UT1-UTC jumps by 1 s across a leap second, so UT1-TAI (continuous) is interpolated and
// converted back with the TAI-UTC of the requested instant.

#include <cstddef>
#include <utility>
#include <string>
#include <vector>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"

namespace visors::core {

struct EarthOrientation {
  double xp = 0.0;    // polar motion x_p [rad]
  double yp = 0.0;    // polar motion y_p [rad]
  double dut1 = 0.0;  // UT1 - UTC [s]
  double lod = 0.0;   // excess length of day [s]
  double dx = 0.0;    // celestial pole offset dX w.r.t. IAU 2006/2000A [rad]
  double dy = 0.0;    // celestial pole offset dY w.r.t. IAU 2006/2000A [rad]
};

class EopTable {
 public:
  /// The values of one day, at 0h UTC.
  struct Row {
    double mjd = 0.0;            // UTC [d], 0h
    double xp = 0.0;             // polar motion x_p [rad]
    double yp = 0.0;             // polar motion y_p [rad]
    double ut1_minus_tai = 0.0;  // UT1 - TAI [s] (continuous across leap seconds)
    double lod = 0.0;            // excess length of day [s]
    double dx = 0.0;             // celestial pole offset dX [rad]
    double dy = 0.0;             // celestial pole offset dY [rad]
  };

  /// The table of `rows`: at least one row, consecutive days (each mjd the previous one + 1),
  /// every value finite. Errors name "rows" or "rows[k]" and the problem.
  static Result<EopTable> create(std::vector<Row> rows);

  /// EOP at `t`, linearly interpolated; an error naming the table's range when `t` is outside.
  [[nodiscard]] Result<EarthOrientation> at(GpsTime t) const;

  [[nodiscard]] std::size_t size() const { return rows_.size(); }
  [[nodiscard]] double first_mjd() const { return rows_.front().mjd; }  // UTC [d]
  [[nodiscard]] double last_mjd() const { return rows_.back().mjd; }    // UTC [d]

 private:
  explicit EopTable(std::vector<Row> rows) : rows_(std::move(rows)) {}
  std::vector<Row> rows_;
};

/// An MJD as written in EOP messages (two decimals).
std::string mjd_text(double mjd);

}  // namespace visors::core
