#include "visors/gnss/files/text_file.hpp"

#include <cctype>
#include <charconv>
#include <algorithm>
#include <cmath>

namespace visors::gnss::files {

namespace {

// "'<text>' is not <what>", built by appending (GCC 12 reports a false -Wrestrict on
// "'" + std::string(...)).
std::string not_a(std::string_view text, const char* what) {
  std::string message(1, '\'');
  message.append(text);
  message.append("' is not ");
  message.append(what);
  return message;
}

}  // namespace

core::Result<TextFile> TextFile::open(const std::filesystem::path& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return core::Error{path.string(), what + " not found or not a regular file"};
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return core::Error{path.string(), "cannot open the " + what + " for reading"};
  return TextFile(path, std::move(in));
}

bool TextFile::next(std::string& line) {
  if (!std::getline(in_, line)) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  ++line_number_;
  return true;
}

core::Error TextFile::error(const std::string& problem) const {
  return core::Error{path_.string() + ":" + std::to_string(line_number_), problem};
}

core::Error TextFile::file_error(const std::string& problem) const { return core::Error{path_.string(), problem}; }

std::string_view column(std::string_view line, std::size_t first, std::size_t width) {
  if (first >= line.size()) return {};
  return line.substr(first, width);
}

std::string_view trim(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return text;
}

core::Result<std::optional<double>> parse_number(std::string_view field, std::string_view name) {
  const std::string_view text = trim(field);
  if (text.empty()) return std::optional<double>{};
  std::string normal(text);
  for (char& c : normal) {
    if (c == 'D' || c == 'd') c = 'E';
  }
  const char* begin = normal.data();
  if (*begin == '+') ++begin;  // from_chars rejects a leading '+'
  double value = 0.0;
  const auto [end, ec] = std::from_chars(begin, normal.data() + normal.size(), value);
  if (ec != std::errc() || end != normal.data() + normal.size() || !std::isfinite(value)) {
    return core::Error{std::string(name), not_a(text, "a number")};
  }
  return std::optional<double>(value);
}

core::Result<std::optional<long long>> parse_integer(std::string_view field, std::string_view name) {
  const std::string_view text = trim(field);
  if (text.empty()) return std::optional<long long>{};
  const char* begin = text.data();
  if (*begin == '+') ++begin;
  long long value = 0;
  const auto [end, ec] = std::from_chars(begin, text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) {
    return core::Error{std::string(name), not_a(text, "an integer")};
  }
  return std::optional<long long>(value);
}

namespace {

std::string field_name(const char* name, const CalendarColumns::Field& f) {
  return std::string(name) + " (columns " + std::to_string(f.first + 1) + "-" + std::to_string(f.first + f.width) + ")";
}

// "ss.sssssss" into second and nanosecond (digits beyond the ninth decimal ignored).
std::optional<core::Error> parse_seconds(std::string_view field, const std::string& name, core::CalendarTime& c) {
  const std::string_view text = trim(field);
  if (text.empty()) return core::Error{name, "is blank"};
  const std::size_t dot = text.find('.');
  const std::string_view whole = text.substr(0, dot);
  const std::string_view fraction = dot == std::string_view::npos ? std::string_view() : text.substr(dot + 1);
  const auto is_digit = [](char ch) { return ch >= '0' && ch <= '9'; };
  if (whole.empty() || whole.size() > 2 || !std::all_of(whole.begin(), whole.end(), is_digit) ||
      !std::all_of(fraction.begin(), fraction.end(), is_digit)) {
    return core::Error{name, not_a(text, "a number of seconds ss.sss")};
  }
  c.second = std::stoi(std::string(whole));
  std::int64_t ns = 0;
  for (std::size_t k = 0; k < 9; ++k) ns = ns * 10 + (k < fraction.size() ? fraction[k] - '0' : 0);
  c.nanosecond = ns;
  return std::nullopt;
}

}  // namespace

core::Result<core::GpsTime> parse_gps_calendar(std::string_view line, const CalendarColumns& columns) {
  const struct {
    const char* name;
    const CalendarColumns::Field& field;
  } parts[] = {{"year", columns.year}, {"month", columns.month}, {"day", columns.day}, {"hour", columns.hour},
               {"minute", columns.minute}};
  int values[5] = {};
  for (std::size_t k = 0; k < 5; ++k) {
    const std::string name = field_name(parts[k].name, parts[k].field);
    const auto value = parse_integer(column(line, parts[k].field.first, parts[k].field.width), name);
    if (!value) return value.error();
    if (!*value) return core::Error{name, "is blank"};
    values[k] = static_cast<int>(**value);
  }
  if (columns.two_digit_year) values[0] += values[0] >= 80 ? 1900 : 2000;
  core::CalendarTime c{values[0], values[1], values[2], values[3], values[4], 0, 0};
  if (auto error = parse_seconds(column(line, columns.second.first, columns.second.width),
                                 field_name("second", columns.second), c)) {
    return *error;
  }
  auto t = core::GpsTime::from_calendar(c, core::TimeScale::kGps);
  if (!t) return core::Error{"epoch", t.error().describe()};
  return t;
}

}  // namespace visors::gnss::files
