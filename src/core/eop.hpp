#pragma once
// Earth orientation parameters (EOP) from an IERS finals2000A file (Bulletin A columns; format:
// USNO readme.finals2000A). Values are daily at 0h UTC; they are interpolated linearly in UTC MJD.
// UT1-UTC jumps by 1 s across a leap second, so UT1-TAI (continuous) is interpolated and
// converted back with the TAI-UTC of the requested instant.

#include <cstddef>
#include <filesystem>
#include <utility>
#include <vector>

#include "core/gps_time.hpp"
#include "core/status.hpp"

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
  /// Parses a finals2000A file. Rows must be consecutive days; rows without polar motion or
  /// UT1-UTC are accepted only at the end (future dates) and are dropped. Blank LOD, dX, dY
  /// (optional in the format) read as 0. A malformed row is an error naming its line number.
  static Result<EopTable> load(const std::filesystem::path& path);

  /// EOP at `t`, linearly interpolated; an error naming the table's range when `t` is outside.
  [[nodiscard]] Result<EarthOrientation> at(GpsTime t) const;

  [[nodiscard]] std::size_t size() const { return rows_.size(); }
  [[nodiscard]] double first_mjd() const { return rows_.front().mjd; }  // UTC [d]
  [[nodiscard]] double last_mjd() const { return rows_.back().mjd; }    // UTC [d]

 private:
  struct Row {
    double mjd = 0.0;           // UTC [d], 0h
    double xp = 0.0;            // [rad]
    double yp = 0.0;            // [rad]
    double ut1_minus_tai = 0.0; // [s]
    double lod = 0.0;           // [s]
    double dx = 0.0;            // [rad]
    double dy = 0.0;            // [rad]
  };
  explicit EopTable(std::vector<Row> rows) : rows_(std::move(rows)) {}
  std::vector<Row> rows_;
};

}  // namespace visors::core
