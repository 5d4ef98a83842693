#include "visors/gnss/files/almanac_file.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "visors/gnss/files/text_file.hpp"
#include "visors/gnss/gps_constants.hpp"

namespace visors::gnss::files {

namespace {

// The full GPS week w with w = week_mod_1024 (mod 1024) nearest the week of `near`.
int full_week(long long week_mod_1024, core::GpsTime near) {
  const int reference = near.week();
  const int base = reference - (reference % 1024);
  int best = base + static_cast<int>(week_mod_1024 % 1024);
  for (int candidate : {best - 1024, best + 1024}) {
    if (std::abs(candidate - reference) < std::abs(best - reference)) best = candidate;
  }
  return best;
}

core::Result<core::GpsTime> applicability(long long week, double toa, core::GpsTime near) {
  return core::GpsTime::from_week_seconds(full_week(week, near), toa);
}

// YUMA keys in block order (the text before ':', compared without blanks and case).
constexpr std::array<const char*, 13> kYumaKeys = {
    "id",           "health",        "eccentricity", "timeofapplicability(s)", "orbitalinclination(rad)",
    "rateofrightascen(r/s)", "sqrt(a)(m1/2)", "rightascenatweek(rad)", "argumentofperigee(rad)", "meananom(rad)",
    "af0(s)",       "af1(s/s)",      "week"};

std::string normal_key(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c != ' ' && c != '\t') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

core::Result<GpsAlmanacEntry> entry_from(const std::array<double, 13>& v, core::GpsTime near) {
  GpsAlmanacEntry e;
  e.prn = static_cast<int>(v[0]);
  e.health = static_cast<int>(v[1]);
  e.eccentricity = v[2];
  e.inclination_rad = v[4];
  e.raan_rate_radps = v[5];
  e.sqrt_a = v[6];
  e.raan_rad = v[7];
  e.arg_perigee_rad = v[8];
  e.mean_anomaly_rad = v[9];
  e.af0_s = v[10];
  e.af1_sps = v[11];
  if (v[12] < 0 || v[12] != std::floor(v[12])) return core::Error{"week", "must be a whole week number"};
  auto toa = applicability(static_cast<long long>(v[12]), v[3], near);
  if (!toa) return core::Error{"time of applicability", toa.error().describe()};
  e.toa = *toa;
  if (auto valid = validate(e); !valid) return valid.error();
  return e;
}

}  // namespace

core::Result<std::vector<GpsAlmanacEntry>> read_yuma_almanac(const std::filesystem::path& path, core::GpsTime near) {
  auto opened = TextFile::open(path, "YUMA almanac");
  if (!opened) return opened.error();
  TextFile file = std::move(opened).value();
  std::vector<GpsAlmanacEntry> entries;
  std::string line;
  std::array<double, 13> values{};
  std::size_t next_key = 0, block_line = 0;
  bool in_block = false;
  const auto finish = [&]() -> std::optional<core::Error> {
    auto entry = entry_from(values, near);
    if (!entry) return core::Error{path.string() + ":" + std::to_string(block_line), entry.error().describe()};
    entries.push_back(*entry);
    in_block = false;
    return std::nullopt;
  };
  while (file.next(line)) {
    const std::string_view text = trim(line);
    if (text.empty()) continue;
    if (text.front() == '*') {
      if (in_block) return file.error("new block before the previous one's '" + std::string(kYumaKeys[next_key]) + "' line");
      in_block = true;
      next_key = 0;
      block_line = file.line_number();
      continue;
    }
    if (!in_block) return file.error("data before the first '********' block header");
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos) return file.error("expected 'Key: value'");
    const std::string key = normal_key(text.substr(0, colon));
    if (key != kYumaKeys[next_key]) {
      return file.error("key '" + std::string(trim(text.substr(0, colon))) + "' where '" + kYumaKeys[next_key] + "' was expected");
    }
    const auto value = parse_number(text.substr(colon + 1), key);
    if (!value) return file.error(value.error().describe());
    if (!*value) return file.error(key + " has no value");
    values[next_key++] = **value;
    if (next_key == kYumaKeys.size()) {
      if (auto error = finish()) return *error;
    }
  }
  if (in_block) return file.error("the last block is truncated after '" + std::string(kYumaKeys[next_key - 1]) + "'");
  if (entries.empty()) return file.file_error("no almanac block");
  return entries;
}

core::Result<std::vector<GpsAlmanacEntry>> read_sem_almanac(const std::filesystem::path& path, core::GpsTime near) {
  auto opened = TextFile::open(path, "SEM almanac");
  if (!opened) return opened.error();
  TextFile file = std::move(opened).value();
  std::string line;
  // The numbers of the file in order, each with its line (blank lines are separators only).
  const auto next_numbers = [&](std::size_t count, const char* what) -> core::Result<std::vector<double>> {
    while (file.next(line)) {
      if (trim(line).empty()) continue;
      std::istringstream in{std::string(trim(line))};
      std::vector<double> out;
      std::string token;
      while (in >> token && out.size() < count) {
        const auto value = parse_number(token, what);
        if (!value) return value.error();
        out.push_back(**value);
      }
      if (out.size() < count) {
        return core::Error{what, "expected " + std::to_string(count) + " numbers, found " + std::to_string(out.size())};
      }
      return out;
    }
    return core::Error{what, "missing (the file ends)"};
  };
  const auto at_line = [&](const core::Error& e) { return core::Error{path.string() + ":" + std::to_string(file.line_number()), e.describe()}; };
  auto count = next_numbers(1, "number of records");
  if (!count) return at_line(count.error());
  const auto header = next_numbers(2, "week and time of applicability");
  if (!header) return at_line(header.error());
  const double week = (*header)[0], toa = (*header)[1];
  const auto n = static_cast<std::size_t>((*count)[0]);
  if ((*count)[0] < 1 || (*count)[0] > 64) return core::Error{path.string() + ":1", "number of records must be in 1..64"};
  std::vector<GpsAlmanacEntry> entries;
  for (std::size_t k = 0; k < n; ++k) {
    std::array<double, 13> v{};
    const char* names[] = {"PRN", "SVN", "URA"};
    double prn = 0.0;
    for (const char* name : names) {
      auto x = next_numbers(1, name);
      if (!x) return at_line(x.error());
      if (std::string(name) == "PRN") prn = (*x)[0];
    }
    const std::size_t first_line = file.line_number();
    std::array<std::vector<double>, 3> rows;
    const char* row_names[] = {"eccentricity, inclination offset, rate of right ascension",
                               "sqrt(A), right ascension at week, argument of perigee",
                               "mean anomaly, af0, af1"};
    for (std::size_t r = 0; r < 3; ++r) {
      auto x = next_numbers(3, row_names[r]);
      if (!x) return at_line(x.error());
      rows[r] = std::move(x).value();
    }
    auto health = next_numbers(1, "health");
    if (!health) return at_line(health.error());
    auto config = next_numbers(1, "configuration");
    if (!config) return at_line(config.error());
    // SEM angles are semicircles; the inclination is an offset from 0.30 semicircles.
    v = {prn,          (*health)[0],           rows[0][0], toa,        (0.30 + rows[0][1]) * kGpsPi,
         rows[0][2] * kGpsPi, rows[1][0], rows[1][1] * kGpsPi, rows[1][2] * kGpsPi, rows[2][0] * kGpsPi,
         rows[2][1],   rows[2][2],             week};
    auto entry = entry_from(v, near);
    if (!entry) return core::Error{path.string() + ":" + std::to_string(first_line), entry.error().describe()};
    entries.push_back(*entry);
  }
  return entries;
}

}  // namespace visors::gnss::files
