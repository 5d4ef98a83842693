#include "visors/gnss/files/rinex_nav_file.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <cmath>
#include <string>

#include "visors/gnss/files/text_file.hpp"

namespace visors::gnss::files {

namespace {

constexpr std::size_t kValueWidth = 19;

// Layout of one version's records (file comment).
struct Layout {
  std::size_t epoch_values = 0;  // first column of a_f0 on the epoch line (0-based)
  std::size_t orbit_values = 0;  // first column of the values on the orbit lines
};

// The 29 numbers of a GPS record in file order: a_f0..a_f2, then 7 orbit lines of 4.
using RecordValues = std::array<std::optional<double>, 3 + 7 * 4>;

// Names of the values, for messages (RINEX 3.05 Table A6).
constexpr std::array<const char*, 31> kValueNames = {
    "SV clock bias a_f0", "SV clock drift a_f1", "SV clock drift rate a_f2",
    "IODE", "Crs", "Delta n", "M0",
    "Cuc", "e", "Cus", "sqrt(A)",
    "Toe", "Cic", "OMEGA0", "Cis",
    "i0", "Crc", "omega", "OMEGA DOT",
    "IDOT", "codes on L2", "GPS week", "L2 P data flag",
    "SV accuracy", "SV health", "TGD", "IODC",
    "transmission time", "fit interval", "spare", "spare"};

class NavigationReader {
 public:
  explicit NavigationReader(TextFile file) : file_(std::move(file)) {}

  core::Result<NavigationFile> read() {
    if (auto error = read_header()) return *error;
    std::string line;
    while (file_.next(line)) {
      if (trim(line).empty()) continue;
      if (auto error = read_record(line)) return *error;
    }
    return std::move(result_);
  }

 private:
  std::optional<core::Error> read_header() {
    std::string line;
    bool first = true;
    while (file_.next(line)) {
      const std::string_view label = trim(column(line, 60, 20));
      if (first) {
        first = false;
        if (label != "RINEX VERSION / TYPE") return file_.error("the first line must be RINEX VERSION / TYPE");
        if (auto error = version_line(line)) return error;
        continue;
      }
      if (label == "END OF HEADER") return std::nullopt;
      if (label == "ION ALPHA" || label == "ION BETA") {
        if (auto error = ionosphere_line(line, 2, label == "ION ALPHA")) return error;
      } else if (label == "IONOSPHERIC CORR") {
        const std::string_view kind = trim(column(line, 0, 4));
        if (kind == "GPSA" || kind == "GPSB") {
          if (auto error = ionosphere_line(line, 5, kind == "GPSA")) return error;
        }
      } else if (label == "LEAP SECONDS") {
        const auto leap = parse_integer(column(line, 0, 6), "leap seconds (columns 1-6)");
        if (!leap) return file_.error(leap.error().describe());
        if (*leap) result_.leap_seconds = static_cast<int>(**leap);
      }
    }
    if (first) return file_.file_error("empty file: not a RINEX navigation file");
    return file_.file_error("no END OF HEADER line: the header is truncated");
  }

  std::optional<core::Error> version_line(std::string_view line) {
    const auto version = parse_number(column(line, 0, 9), "version (columns 1-9)");
    if (!version) return file_.error(version.error().describe());
    if (!*version) return file_.error("version (columns 1-9) is blank");
    result_.version = **version;
    const char type = column(line, 20, 1).empty() ? ' ' : line[20];
    if (result_.version >= 2.0 && result_.version < 3.0) {
      if (type != 'N') return file_.error("file type (column 21) '" + std::string(1, type) + "' is not N (GPS navigation)");
      layout_ = {22, 3};
      rinex3_ = false;
    } else if (result_.version >= 3.0 && result_.version < 4.0) {
      if (type != 'N') return file_.error("file type (column 21) '" + std::string(1, type) + "' is not N (navigation)");
      const char system = column(line, 40, 1).empty() ? 'G' : line[40];
      if (system != 'G' && system != 'M' && system != ' ') {
        return file_.error("satellite system (column 41) '" + std::string(1, system) + "' has no GPS records");
      }
      layout_ = {23, 4};
      rinex3_ = true;
    } else {
      return file_.error("version " + std::string(trim(column(line, 0, 9))) + " is not supported (2.x or 3.x)");
    }
    return std::nullopt;
  }

  std::optional<core::Error> ionosphere_line(std::string_view line, std::size_t first, bool alpha) {
    KlobucharCoefficients coefficients = result_.ionosphere.value_or(KlobucharCoefficients{});
    auto& target = alpha ? coefficients.alpha : coefficients.beta;
    for (std::size_t k = 0; k < 4; ++k) {
      const std::string name = std::string(alpha ? "alpha" : "beta") + std::to_string(k);
      const auto value = parse_number(column(line, first + 12 * k, 12), name);
      if (!value) return file_.error(value.error().describe());
      if (!*value) return file_.error(name + " is blank");
      target[k] = **value;
    }
    result_.ionosphere = coefficients;
    return std::nullopt;
  }

  // Line count of a record of `system` (RINEX 3.05 section 6).
  static int record_lines(char system) { return (system == 'R' || system == 'S') ? 4 : 8; }

  std::optional<core::Error> read_record(const std::string& epoch_line) {
    const std::size_t start_line = file_.line_number();
    char system = 'G';
    int prn = 0;
    if (rinex3_) {
      system = epoch_line[0];
      if (system != 'G') return skip_lines(record_lines(system) - 1, epoch_line);
    }
    const auto prn_value = parse_integer(rinex3_ ? column(epoch_line, 1, 2) : column(epoch_line, 0, 2),
                                         rinex3_ ? "PRN (columns 2-3)" : "PRN (columns 1-2)");
    if (!prn_value) return file_.error(prn_value.error().describe());
    if (!*prn_value || **prn_value < 1 || **prn_value > 32) return file_.error("PRN must be in 1..32");
    prn = static_cast<int>(**prn_value);

    const auto toc = epoch(epoch_line);
    if (!toc) return file_.error(toc.error().describe());
    RecordValues values;
    if (auto error = read_values(epoch_line, layout_.epoch_values, 3, values, 0)) return error;
    std::string line;
    for (std::size_t row = 0; row < 7; ++row) {
      if (!file_.next(line)) {
        return file_.error("record of G" + std::to_string(prn) + " starting at line " + std::to_string(start_line) +
                           " is truncated: broadcast orbit " + std::to_string(row + 1) + " of 7 is missing");
      }
      const std::size_t count = row == 6 ? 2 : 4;  // line 7 holds the transmission time and fit interval
      if (auto error = read_values(line, layout_.orbit_values, count, values, 3 + 4 * row)) return error;
    }
    auto record = make_record(prn, *toc, values);
    if (!record) return core::Error{file_.path().string() + ":" + std::to_string(start_line), record.error().describe()};
    result_.records.push_back(*record);
    result_.record_lines.push_back(start_line);
    return std::nullopt;
  }

  std::optional<core::Error> skip_lines(int count, const std::string& epoch_line) {
    std::string line;
    for (int k = 0; k < count; ++k) {
      if (!file_.next(line)) {
        return file_.error("record '" + std::string(column(epoch_line, 0, 3)) + "' is truncated");
      }
    }
    return std::nullopt;
  }

  core::Result<core::GpsTime> epoch(std::string_view line) const {
    // RINEX 3: A1 I2.2 1X I4 5(1X I2.2); RINEX 2: I2 1X I2.2 4(1X I2) F5.1 (the second's field
    // includes the separating blank).
    static constexpr CalendarColumns kRinex3{{4, 4}, {9, 2}, {12, 2}, {15, 2}, {18, 2}, {21, 2}};
    static constexpr CalendarColumns kRinex2{{3, 2}, {6, 2}, {9, 2}, {12, 2}, {15, 2}, {17, 5}, true};
    auto t = parse_gps_calendar(line, rinex3_ ? kRinex3 : kRinex2);
    if (!t) return core::Error{"t_oc", t.error().describe()};
    return t;
  }

  std::optional<core::Error> read_values(std::string_view line, std::size_t first, std::size_t count,
                                         RecordValues& values, std::size_t offset) {
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t start = first + kValueWidth * k;
      const std::string name = std::string(kValueNames[offset + k]) + " (columns " + std::to_string(start + 1) + "-" +
                               std::to_string(start + kValueWidth) + ")";
      const auto value = parse_number(column(line, start, kValueWidth), name);
      if (!value) return file_.error(value.error().describe());
      values[offset + k] = *value;
    }
    return std::nullopt;
  }

  static core::Result<BroadcastEphemeris> make_record(int prn, core::GpsTime toc, const RecordValues& v) {
    // Values that may be blank: codes on L2 (20), L2 P flag (22), transmission time (27), fit (28).
    for (std::size_t k = 0; k < 27; ++k) {
      if (k == 20 || k == 22) continue;
      if (!v[k]) return core::Error{kValueNames[k], "is blank"};
    }
    BroadcastEphemeris e;
    e.prn = prn;
    e.toc = toc;
    e.af0_s = *v[0];
    e.af1_sps = *v[1];
    e.af2_sps2 = *v[2];
    e.iode = static_cast<int>(std::lround(*v[3]));
    e.crs_m = *v[4];
    e.delta_n_radps = *v[5];
    e.m0_rad = *v[6];
    e.cuc_rad = *v[7];
    e.eccentricity = *v[8];
    e.cus_rad = *v[9];
    e.sqrt_a = *v[10];
    e.cic_rad = *v[12];
    e.omega0_rad = *v[13];
    e.cis_rad = *v[14];
    e.i0_rad = *v[15];
    e.crc_m = *v[16];
    e.omega_rad = *v[17];
    e.omega_dot_radps = *v[18];
    e.idot_radps = *v[19];
    e.ura_m = *v[23];
    e.health = static_cast<int>(std::lround(*v[24]));
    e.tgd_s = *v[25];
    e.iodc = static_cast<int>(std::lround(*v[26]));
    const double week = *v[21];
    if (!(week >= 0.0 && week < 1e5 && week == std::floor(week))) return core::Error{"GPS week", "must be a whole week number"};
    auto toe = core::GpsTime::from_week_seconds(static_cast<int>(week), *v[11]);
    if (!toe) return core::Error{"Toe", toe.error().describe()};
    e.toe = *toe;
    e.transmission = e.toe;
    if (v[27] && std::abs(*v[27]) < 9e8) {
      // Seconds of the week of t_oe; a value more than half a week away belongs to the next/previous week.
      double seconds = *v[27];
      const double toe_sow = e.toe.seconds_of_week();
      if (seconds - toe_sow > 302400.0) seconds -= 604800.0;
      if (seconds - toe_sow < -302400.0) seconds += 604800.0;
      e.transmission = e.toe + (seconds - toe_sow);
    }
    if (v[28]) {
      const double fit = *v[28];
      if (!std::isfinite(fit) || fit < 0.0) return core::Error{"fit interval", "must be >= 0"};
      e.fit_interval_h = fit == 0.0 ? 4.0 : fit == 1.0 ? 6.0 : fit;  // ICD flag stored by some writers
    }
    return e;
  }

  TextFile file_;
  NavigationFile result_;
  Layout layout_;
  bool rinex3_ = false;
};

// One D19.12 field (RINEX 3.05 Table A6), e.g. " 1.234567890123E-05".
std::string value_field(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%19.12E", value);
  return text;
}

std::string fmt_leap(int seconds) {
  char text[16];
  std::snprintf(text, sizeof text, "%6d", seconds);
  return text;
}

std::string header_line(const std::string& content, const char* label) {
  char text[96];
  std::snprintf(text, sizeof text, "%-60.60s%-20s", content.c_str(), label);
  return text;
}

std::string record_text(const BroadcastEphemeris& e) {
  const core::CalendarTime c = e.toc.calendar(core::TimeScale::kGps);
  char epoch[40];
  std::snprintf(epoch, sizeof epoch, "G%02d %04d %02d %02d %02d %02d %02d", e.prn, c.year, c.month, c.day, c.hour, c.minute,
                c.second);
  const double transmission_sow = e.toe.seconds_of_week() + e.transmission.seconds_since(e.toe);
  const double rows[7][4] = {
      {static_cast<double>(e.iode), e.crs_m, e.delta_n_radps, e.m0_rad},
      {e.cuc_rad, e.eccentricity, e.cus_rad, e.sqrt_a},
      {e.toe.seconds_of_week(), e.cic_rad, e.omega0_rad, e.cis_rad},
      {e.i0_rad, e.crc_m, e.omega_rad, e.omega_dot_radps},
      {e.idot_radps, 1.0, static_cast<double>(e.toe.week()), 0.0},
      {e.ura_m, static_cast<double>(e.health), e.tgd_s, static_cast<double>(e.iodc)},
      {transmission_sow, e.fit_interval_h, 0.0, 0.0}};
  std::string text = std::string(epoch) + value_field(e.af0_s) + value_field(e.af1_sps) + value_field(e.af2_sps2) + "\n";
  for (int row = 0; row < 7; ++row) {
    text += "    ";
    for (int k = 0; k < (row == 6 ? 2 : 4); ++k) text += value_field(rows[row][k]);
    text += "\n";
  }
  return text;
}

}  // namespace

core::Result<bool> write_rinex3_navigation(const std::filesystem::path& path, const NavigationFile& file,
                                           const std::string& program) {
  std::ofstream out(path);
  if (!out) return core::Error{path.string(), "cannot open the RINEX navigation file for writing"};
  out << header_line("     3.05           N: GNSS NAV DATA    G: GPS", "RINEX VERSION / TYPE") << "\n";
  out << header_line(program, "PGM / RUN BY / DATE") << "\n";
  if (file.ionosphere) {
    for (const bool alpha : {true, false}) {
      const auto& v = alpha ? file.ionosphere->alpha : file.ionosphere->beta;
      char content[64];
      std::snprintf(content, sizeof content, "%s %12.4E%12.4E%12.4E%12.4E", alpha ? "GPSA" : "GPSB", v[0], v[1], v[2], v[3]);
      out << header_line(content, "IONOSPHERIC CORR") << "\n";
    }
  }
  if (file.leap_seconds) out << header_line(fmt_leap(*file.leap_seconds), "LEAP SECONDS") << "\n";
  out << header_line("", "END OF HEADER") << "\n";
  for (const auto& record : file.records) out << record_text(record);
  if (!out) return core::Error{path.string(), "write failed"};
  return true;
}

core::Result<NavigationFile> read_rinex_navigation(const std::filesystem::path& path) {
  auto file = TextFile::open(path, "RINEX navigation file");
  if (!file) return file.error();
  return NavigationReader(std::move(file).value()).read();
}

}  // namespace visors::gnss::files
