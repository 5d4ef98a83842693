#include "visors/core/files/eop_file.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "visors/core/constants.hpp"

namespace visors::core::files {
namespace {

constexpr double kMasToRad = kArcsecToRad * 1e-3;

// A fixed-width field of finals2000A, 1-based inclusive columns as in readme.finals2000A.
struct Column {
  const char* name;
  std::size_t first;
  std::size_t last;
};
constexpr Column kYear{"year", 1, 2};
constexpr Column kMonth{"month", 3, 4};
constexpr Column kDay{"day", 5, 6};
constexpr Column kMjd{"MJD", 8, 15};
constexpr Column kPolarFlag{"polar motion flag", 17, 17};
constexpr Column kXp{"x_p", 19, 27};       // [arcsec]
constexpr Column kYp{"y_p", 38, 46};       // [arcsec]
constexpr Column kUt1Flag{"UT1-UTC flag", 58, 58};
constexpr Column kUt1{"UT1-UTC", 59, 68};  // [s]
constexpr Column kLod{"LOD", 80, 86};      // [ms]
constexpr Column kDx{"dX", 98, 106};       // [mas]
constexpr Column kDy{"dY", 117, 125};      // [mas]

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::string_view field(std::string_view line, const Column& c) {
  if (line.size() < c.first) return {};
  return trimmed(line.substr(c.first - 1, c.last - c.first + 1));
}

std::string columns(const Column& c) {
  return std::string(c.name) + " (columns " + std::to_string(c.first) + "-" + std::to_string(c.last) +
         ")";
}

struct LineError {
  std::string message;
};

// nullopt for a blank field; throws nothing: a bad number is reported through `error`.
std::optional<double> number(std::string_view line, const Column& c, std::optional<LineError>& error) {
  const std::string_view text = field(line, c);
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    if (!error) error = LineError{columns(c) + ": '" + std::string(text) + "' is not a number"};
    return std::nullopt;
  }
  return value;
}

bool valid_flag(std::string_view line, const Column& c) {
  const std::string_view f = field(line, c);
  return f.empty() || f == "I" || f == "P";
}

Error line_error(std::size_t line_number, std::string message) {
  return Error{"line " + std::to_string(line_number), std::move(message)};
}

}  // namespace

Result<EopTable> read_eop_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return Error{"", "cannot open EOP file '" + path.string() + "'"};

  std::vector<EopTable::Row> rows;
  std::size_t first_empty_line = 0;  // first row without values: only such rows may follow
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (trimmed(line).empty()) continue;

    std::optional<LineError> error;
    const auto yy = number(line, kYear, error);
    const auto mm = number(line, kMonth, error);
    const auto dd = number(line, kDay, error);
    const auto mjd = number(line, kMjd, error);
    const auto xp = number(line, kXp, error);
    const auto yp = number(line, kYp, error);
    const auto ut1 = number(line, kUt1, error);
    const auto lod = number(line, kLod, error);
    const auto dx = number(line, kDx, error);
    const auto dy = number(line, kDy, error);
    if (error) return line_error(line_number, error->message);
    if (!yy || !mm || !dd || !mjd) {
      return line_error(line_number, "date (columns 1-6) and MJD (columns 8-15) are required");
    }
    for (const Column* c : {&kPolarFlag, &kUt1Flag}) {
      if (!valid_flag(line, *c)) return line_error(line_number, columns(*c) + ": must be I, P or blank");
    }
    // Two-digit year: 19xx up to MJD 51543 (1999-12-31), 20xx after (readme.finals2000A).
    CalendarTime date;
    date.year = static_cast<int>(*yy) + (*mjd <= 51543.0 ? 1900 : 2000);
    date.month = static_cast<int>(*mm);
    date.day = static_cast<int>(*dd);
    const auto day_start = GpsTime::from_calendar(date, TimeScale::kUtc);
    if (!day_start.ok()) {
      return line_error(line_number, "date (columns 1-6): " + day_start.error().describe());
    }
    if (std::abs(day_start->jd_utc().mjd() - *mjd) > 1e-6) {
      return line_error(line_number, "date (columns 1-6) " + std::string(field(line, {"", 1, 6})) +
                                         " does not match MJD " + mjd_text(*mjd));
    }
    const int present = (xp ? 1 : 0) + (yp ? 1 : 0) + (ut1 ? 1 : 0);
    if (present != 0 && present != 3) {
      return line_error(line_number, "x_p, y_p and UT1-UTC must be all present or all blank");
    }
    if (present == 0) {  // a future date without values (the end of a finals.all file)
      if (first_empty_line == 0) first_empty_line = line_number;
      continue;
    }
    if (first_empty_line != 0) {
      return line_error(first_empty_line, "has no x_p, y_p, UT1-UTC but data follows at line " +
                                              std::to_string(line_number) +
                                              " (rows without values may only end the file)");
    }
    if (!rows.empty() && *mjd != rows.back().mjd + 1.0) {
      return line_error(line_number, "MJD " + mjd_text(*mjd) + " does not follow " +
                                         mjd_text(rows.back().mjd) + " (rows must be consecutive days)");
    }
    EopTable::Row row;
    row.mjd = *mjd;
    row.xp = *xp * kArcsecToRad;
    row.yp = *yp * kArcsecToRad;
    row.ut1_minus_tai = *ut1 - day_start->tai_minus_utc();
    row.lod = lod.value_or(0.0) * 1e-3;  // ms -> s
    row.dx = dx.value_or(0.0) * kMasToRad;
    row.dy = dy.value_or(0.0) * kMasToRad;
    rows.push_back(row);
  }
  if (rows.empty()) return Error{"", "no EOP rows in '" + path.string() + "'"};
  return EopTable::create(std::move(rows));  // the checks above leave nothing for it to reject
}

}  // namespace visors::core::files
