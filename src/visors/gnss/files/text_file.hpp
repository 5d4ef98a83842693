#pragma once
// Line-oriented reading of the fixed-column GNSS exchange formats (RINEX, SP3, YUMA, SEM), ground
// side. Every error names the file and the 1-based line, as "<path>:<line>" in Error::field, so a
// user can open the offending line directly.
//
// Numbers: RINEX 2 (and some RINEX 3 writers) use Fortran 'D' exponents ("0.4657D-08"); both 'D'
// and 'E' (either case) are accepted. A blank field is "absent", which the caller decides about.

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"

namespace visors::gnss::files {

class TextFile {
 public:
  /// Opens `path`; `what` names the format in messages ("RINEX navigation file").
  static core::Result<TextFile> open(const std::filesystem::path& path, const std::string& what);

  /// The next line without its end-of-line characters (CR of CRLF files removed); false at end.
  bool next(std::string& line);
  /// 1-based number of the line last returned by next() (0 before the first).
  [[nodiscard]] std::size_t line_number() const { return line_number_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  /// Error at the current line: field "<path>:<line>".
  [[nodiscard]] core::Error error(const std::string& problem) const;
  /// Error about the whole file (missing header, no data): field "<path>".
  [[nodiscard]] core::Error file_error(const std::string& problem) const;

 private:
  TextFile(std::filesystem::path path, std::ifstream in) : path_(std::move(path)), in_(std::move(in)) {}
  std::filesystem::path path_;
  std::ifstream in_;
  std::size_t line_number_ = 0;
};

/// Columns [first, first + width) of `line` (0-based), clipped to the line; may be shorter or empty.
std::string_view column(std::string_view line, std::size_t first, std::size_t width);
/// `text` without leading and trailing blanks.
std::string_view trim(std::string_view text);

/// A finite number in Fortran or C notation filling the trimmed field; nullopt when blank.
/// Malformed text (letters, two numbers, non-finite) is an error naming `name`.
core::Result<std::optional<double>> parse_number(std::string_view field, std::string_view name);
/// As parse_number, but an integer value.
core::Result<std::optional<long long>> parse_integer(std::string_view field, std::string_view name);

/// Where the calendar fields of a GPS-time epoch sit on a line (0-based first column, width).
struct CalendarColumns {
  struct Field {
    std::size_t first = 0, width = 0;
  };
  Field year, month, day, hour, minute, second;
  bool two_digit_year = false;  // RINEX 2: yy >= 80 is 19yy, else 20yy
};

/// The GPS time written in `line` at `columns`. The seconds ("ss.sss...", up to 9 decimals used)
/// are read as decimal digits, exactly to the nanosecond, not through a binary double. Errors name
/// the field and its 1-based columns ("month (columns 9-10)"), or "epoch" for an invalid date.
core::Result<core::GpsTime> parse_gps_calendar(std::string_view line, const CalendarColumns& columns);

}  // namespace visors::gnss::files
