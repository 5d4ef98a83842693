#include "visors/gnss/files/rinex_obs_file.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>

#include "visors/gnss/files/rinex_obs_common.hpp"
#include "visors/gnss/files/text_file.hpp"
#include "visors/gnss/gps_constants.hpp"

namespace visors::gnss::files {

namespace {

constexpr std::size_t kMaxTypesPerLine = 13;  // SYS / # / OBS TYPES: 13 codes per line
constexpr std::size_t kValueWidth = 16;       // F14.3 + LLI (I1) + SSI (I1)
constexpr std::int64_t kTickNs = 100;         // the epoch's F11.7 seconds resolve 0.1 us

void header_line(std::FILE* f, const std::string& content, const char* label) {
  std::fprintf(f, "%-60.60s%-20s\n", content.c_str(), label);
}

std::string fields(std::initializer_list<std::pair<const std::string*, int>> parts) {
  std::string out;
  for (const auto& [text, width] : parts) {
    std::string field = text->substr(0, static_cast<std::size_t>(width));
    field.resize(static_cast<std::size_t>(width), ' ');
    out += field;
  }
  return out;
}

// printf of one number into exactly `width` characters, or nullopt when it does not fit (or is
// not finite): a wider field would shift every following column.
std::optional<std::string> fixed(double value, int width, int decimals) {
  if (!std::isfinite(value)) return std::nullopt;
  char text[64];
  const int n = std::snprintf(text, sizeof text, "%*.*f", width, decimals, value);
  if (n != width) return std::nullopt;
  return std::string(text);
}

std::optional<std::string> vector_fields(const Eigen::Vector3d& v) {
  std::string out;
  for (int k = 0; k < 3; ++k) {
    const auto field = fixed(v(k), 14, 4);
    if (!field) return std::nullopt;
    out += *field;
  }
  return out;
}

// The calendar of t rounded to the format's 0.1 us, and the seconds as "ss.sssssss" (width 2 + 8).
std::pair<core::CalendarTime, std::string> rounded_calendar(core::GpsTime t) {
  std::int64_t ns = t.nanoseconds();
  const std::int64_t rest = ((ns % kTickNs) + kTickNs) % kTickNs;
  ns += rest >= kTickNs / 2 ? kTickNs - rest : -rest;
  const core::CalendarTime c = core::GpsTime::from_nanoseconds(ns).calendar(core::TimeScale::kGps);
  char seconds[24];
  std::snprintf(seconds, sizeof seconds, "%2d.%07lld", c.second, static_cast<long long>(c.nanosecond / kTickNs));
  return {c, seconds};
}

std::string epoch_text(core::GpsTime t) {
  const auto [c, seconds] = rounded_calendar(t);
  char text[48];
  std::snprintf(text, sizeof text, "%04d %02d %02d %02d %02d %s", c.year, c.month, c.day, c.hour, c.minute,
                seconds.c_str());
  return text;
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y%m%d %H%M%S UTC", &utc);
  return text;
}

std::optional<core::Error> write_header(std::FILE* f, const ObservationHeader& h) {
  const auto approx = vector_fields(h.approx_position_m);
  const auto hen = vector_fields(h.antenna_delta_hen_m);
  const auto xyz = h.antenna_delta_xyz_m ? vector_fields(*h.antenna_delta_xyz_m) : std::optional<std::string>("");
  const auto sight = h.antenna_boresight_xyz ? vector_fields(*h.antenna_boresight_xyz) : std::optional<std::string>("");
  if (!approx) return core::Error{"approx_position_m", "does not fit APPROX POSITION XYZ (3F14.4)"};
  if (!hen) return core::Error{"antenna_delta_hen_m", "does not fit ANTENNA: DELTA H/E/N (3F14.4)"};
  if (!xyz) return core::Error{"antenna_delta_xyz_m", "does not fit ANTENNA: DELTA X/Y/Z (3F14.4)"};
  if (!sight) return core::Error{"antenna_boresight_xyz", "does not fit ANTENNA: B.SIGHT XYZ (3F14.4)"};
  const auto interval = fixed(h.interval_s, 10, 3);
  if (h.interval_s > 0.0 && !interval) return core::Error{"interval_s", "does not fit INTERVAL (F10.3)"};

  header_line(f, "     3.05           OBSERVATION DATA    G: GPS", "RINEX VERSION / TYPE");
  const std::string date = h.creation_date.empty() ? utc_now() : h.creation_date;
  header_line(f, fields({{&h.program, 20}, {&h.run_by, 20}, {&date, 20}}), "PGM / RUN BY / DATE");
  for (const auto& comment : h.comments) header_line(f, comment, "COMMENT");
  header_line(f, h.marker_name, "MARKER NAME");
  header_line(f, h.marker_type, "MARKER TYPE");
  header_line(f, fields({{&h.observer, 20}, {&h.agency, 40}}), "OBSERVER / AGENCY");
  header_line(f, fields({{&h.receiver_number, 20}, {&h.receiver_type, 20}, {&h.receiver_version, 20}}), "REC # / TYPE / VERS");
  header_line(f, fields({{&h.antenna_number, 20}, {&h.antenna_type, 20}}), "ANT # / TYPE");
  header_line(f, *approx, "APPROX POSITION XYZ");
  header_line(f, *hen, "ANTENNA: DELTA H/E/N");
  if (h.antenna_delta_xyz_m) header_line(f, *xyz, "ANTENNA: DELTA X/Y/Z");
  if (h.antenna_boresight_xyz) header_line(f, *sight, "ANTENNA: B.SIGHT XYZ");
  char count[16];
  std::snprintf(count, sizeof count, "G  %3zu", h.observation_types.size());
  std::string types = count;
  for (std::size_t k = 0; k < h.observation_types.size(); ++k) {
    if (k > 0 && k % kMaxTypesPerLine == 0) {
      header_line(f, types, "SYS / # / OBS TYPES");
      types = "      ";
    }
    types += " " + h.observation_types[k];
  }
  header_line(f, types, "SYS / # / OBS TYPES");
  if (h.interval_s > 0.0) header_line(f, *interval, "INTERVAL");
  const auto [c, seconds] = rounded_calendar(h.first_observation);
  char first[64];
  std::snprintf(first, sizeof first, "%6d%6d%6d%6d%6d   %s     GPS", c.year, c.month, c.day, c.hour, c.minute,
                seconds.c_str());
  header_line(f, first, "TIME OF FIRST OBS");
  header_line(f, "", "END OF HEADER");
  return std::nullopt;
}

}  // namespace

core::Result<Rinex3ObservationWriter> Rinex3ObservationWriter::open(const std::filesystem::path& path,
                                                                    const ObservationHeader& header) {
  if (header.observation_types.empty()) return core::Error{"observation_types", "must not be empty"};
  if (header.observation_types.size() > 999) return core::Error{"observation_types", "more than 999 types"};
  for (const auto& type : header.observation_types) {
    if (type.size() != 3 || type.find(' ') != std::string::npos) {
      return core::Error{"observation_types", "'" + type + "' is not a 3-character RINEX 3 code"};
    }
  }
  core::files::OutputFile f = core::files::open_output_file(path);
  if (!f) return core::Error{path.string(), "cannot open the RINEX observation file for writing"};
  std::FILE* raw = f.get();
  Rinex3ObservationWriter writer(path, std::move(f), header.observation_types);
  if (auto error = write_header(raw, header)) return *error;
  return writer;
}

core::Result<bool> Rinex3ObservationWriter::write(const ObservationEpoch& epoch) {
  if (!file_) return core::Error{path_.string(), "write after close"};
  const std::string where = "epoch " + epoch.t.format(core::TimeScale::kGps, 3);
  if (epoch.flag < 0 || epoch.flag > 1) return core::Error{where + ".flag", "must be 0 or 1"};
  if (epoch.satellites.size() > 999) return core::Error{where, "more than 999 satellites"};
  std::string text = "> " + epoch_text(epoch.t);
  char head[48];
  std::snprintf(head, sizeof head, "  %1d%3zu", epoch.flag, epoch.satellites.size());
  text += head;
  if (epoch.receiver_clock_offset_s) {
    const auto clock = fixed(*epoch.receiver_clock_offset_s, 15, 12);
    if (!clock) return core::Error{where + ".receiver_clock_offset_s", "does not fit F15.12 (-10 s < offset < 100 s)"};
    text += "      " + *clock;
  }
  text += "\n";
  for (const auto& sat : epoch.satellites) {
    const std::string name = where + ".G" + (sat.prn < 10 && sat.prn >= 0 ? "0" : "") + std::to_string(sat.prn);
    if (sat.prn < 1 || sat.prn > kMaxGpsPrn) return core::Error{name, "PRN must be in 1..32"};
    if (sat.values.size() != types_) {
      return core::Error{name, "has " + std::to_string(sat.values.size()) + " values, the header " +
                                   std::to_string(types_) + " observation types"};
    }
    char id[8];
    std::snprintf(id, sizeof id, "G%02d", sat.prn);
    text += id;
    for (std::size_t k = 0; k < sat.values.size(); ++k) {
      const ObservationValue& v = sat.values[k];
      const std::string value_name = name + "." + types_names_[k];
      if (v.lli < 0 || v.lli > 7) return core::Error{value_name, "LLI must be in 0..7"};
      if (v.ssi < 0 || v.ssi > 9) return core::Error{value_name, "signal strength must be in 0..9"};
      if (v.value) {
        const auto field = fixed(*v.value, 14, 3);
        if (!field) return core::Error{value_name, "value does not fit F14.3 (must be finite, > -1e9, < 1e10)"};
        text += *field;
      } else {
        text.append(14, ' ');
      }
      text += v.lli == 0 ? ' ' : static_cast<char>('0' + v.lli);
      text += v.ssi == 0 ? ' ' : static_cast<char>('0' + v.ssi);
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    text += "\n";
  }
  if (std::fputs(text.c_str(), file_.get()) < 0) return core::Error{path_.string(), "write failed"};
  return true;
}

core::Result<bool> Rinex3ObservationWriter::close() {
  std::FILE* f = file_.release();
  if (f == nullptr) return true;
  const bool ok = std::fflush(f) == 0 && std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) return core::Error{path_.string(), "write failed"};
  return true;
}

core::Result<bool> write_rinex3_observations(const std::filesystem::path& path, const ObservationHeader& header,
                                             std::span<const ObservationEpoch> epochs) {
  auto opened = Rinex3ObservationWriter::open(path, header);
  if (!opened.ok()) return opened.error();
  Rinex3ObservationWriter writer = std::move(opened).value();
  for (const auto& epoch : epochs) {
    if (auto ok = writer.write(epoch); !ok) return ok;
  }
  return writer.close();
}

core::Result<bool> write_rinex3_observations(const std::filesystem::path& path, const ObservationFile& file) {
  return write_rinex3_observations(path, file.header, file.epochs);
}

namespace {

// RINEX 3.0x header after line 1, then the epoch records.
class ObservationReader {
 public:
  ObservationReader(TextFile file, double version) : file_(std::move(file)) { result_.version = version; }

  core::Result<ObservationFile> read() {
    if (auto error = read_header()) return *error;
    std::string line;
    while (file_.next(line)) {
      if (trim(line).empty()) continue;
      if (line[0] != '>') return file_.error("expected an epoch record starting with '>'");
      if (auto error = read_epoch(line)) return *error;
    }
    return std::move(result_);
  }

 private:
  std::optional<core::Error> read_header() {
    std::string line;
    while (file_.next(line)) {
      const std::string_view label = trim(column(line, 60, 20));
      if (label == "END OF HEADER") {
        if (!types_seen_) return file_.error("no SYS / # / OBS TYPES line for GPS (G) before END OF HEADER");
        if (result_.header.observation_types.size() != announced_types_) {
          return file_.error("SYS / # / OBS TYPES announces " + std::to_string(announced_types_) + " GPS types, " +
                             std::to_string(result_.header.observation_types.size()) + " are listed");
        }
        return std::nullopt;
      }
      if (label == "SYS / # / OBS TYPES") {
        if (auto error = observation_types(line)) return error;
      } else if (auto error = detail::read_common_header_record(file_, label, line, result_.header)) {
        return error;
      }
    }
    return file_.error("the file ends here without an END OF HEADER line: the header is truncated");
  }

  // Continuation lines have a blank system letter and continue the last system's list.
  std::optional<core::Error> observation_types(std::string_view line) {
    const char system = line.empty() ? ' ' : line[0];
    if (system != ' ') {
      current_system_ = system;
      const auto count = parse_integer(column(line, 3, 3), "number of types (columns 4-6)");
      if (!count || !*count || **count < 1) return file_.error("number of types (columns 4-6) must be a positive integer");
      if (system == 'G') {
        if (types_seen_) return file_.error("a second SYS / # / OBS TYPES line for G");
        types_seen_ = true;
        announced_types_ = static_cast<std::size_t>(**count);
        result_.header.observation_types.clear();
      }
    }
    if (current_system_ != 'G') return std::nullopt;
    for (std::size_t k = 0; k < kMaxTypesPerLine && result_.header.observation_types.size() < announced_types_; ++k) {
      const std::string_view code = trim(column(line, 7 + 4 * k, 3));
      if (code.size() != 3) return file_.error("observation type " + std::to_string(k + 1) + " (columns " +
                                               std::to_string(8 + 4 * k) + "-" + std::to_string(10 + 4 * k) + ") is missing");
      result_.header.observation_types.emplace_back(code);
    }
    return std::nullopt;
  }

  std::optional<core::Error> read_epoch(const std::string& line) {
    // "> 2024 10 01 00 00  0.0000000  0 12      -0.000123456789": 1-based columns 3-6 year,
    // 8-9, 11-12, 14-15, 17-18, 19-29 second, 32 flag, 33-35 count, 42-56 clock offset.
    const auto flag = parse_integer(column(line, 31, 1), "epoch flag (column 32)");
    if (!flag || !*flag || **flag < 0 || **flag > 6) return file_.error("epoch flag (column 32) must be a digit 0-6");
    const auto count = parse_integer(column(line, 32, 3), "number of satellites (columns 33-35)");
    if (!count) return file_.error(count.error().describe());
    if (!*count || **count < 0) return file_.error("number of satellites / records (columns 33-35) is missing");
    const auto lines = static_cast<std::size_t>(**count);
    if (**flag >= 2) return skip(lines);  // event records: special header lines, or cycle-slip records
    static constexpr CalendarColumns kEpoch{{2, 4}, {7, 2}, {10, 2}, {13, 2}, {16, 2}, {18, 11}};
    auto t = parse_gps_calendar(line, kEpoch);
    if (!t) return file_.error("epoch record: " + t.error().describe());
    ObservationEpoch epoch;
    epoch.t = *t;
    epoch.flag = static_cast<int>(**flag);
    const auto clock = parse_number(column(line, 41, 15), "receiver clock offset (columns 42-56)");
    if (!clock) return file_.error(clock.error().describe());
    epoch.receiver_clock_offset_s = *clock;
    std::string record;
    for (std::size_t k = 0; k < lines; ++k) {
      if (!file_.next(record)) {
        return file_.error("the epoch announces " + std::to_string(lines) + " satellites, the file ends after " +
                           std::to_string(k) + " (truncated)");
      }
      const char system = record.empty() ? ' ' : record[0];
      if (system == '>') {
        return file_.error("the epoch announces " + std::to_string(lines) + " satellites, the next epoch record "
                           "starts after " + std::to_string(k) + " (truncated epoch)");
      }
      if (std::string_view("GRECJIS").find(system) == std::string_view::npos) {
        return file_.error("satellite system (column 1) '" + std::string(1, system) +
                           "' is not one of G R E C J I S: not a satellite record");
      }
      if (system != 'G') continue;
      auto sat = satellite(record);
      if (!sat) return file_.error(sat.error().describe());
      epoch.satellites.push_back(std::move(sat).value());
    }
    result_.epochs.push_back(std::move(epoch));
    return std::nullopt;
  }

  core::Result<SatelliteObservations> satellite(std::string_view record) const {
    const auto prn = parse_integer(column(record, 1, 2), "satellite number (columns 2-3)");
    if (!prn) return prn.error();
    if (!*prn || **prn < 1 || **prn > kMaxGpsPrn) return core::Error{"satellite number (columns 2-3)", "must be in 1..32"};
    SatelliteObservations sat;
    sat.prn = static_cast<int>(**prn);
    for (std::size_t k = 0; k < result_.header.observation_types.size(); ++k) {
      auto value = detail::parse_observation_field(record, 3 + kValueWidth * k, result_.header.observation_types[k]);
      if (!value) return value.error();
      sat.values.push_back(*value);
    }
    return sat;
  }

  std::optional<core::Error> skip(std::size_t lines) {
    std::string ignored;
    for (std::size_t k = 0; k < lines; ++k) {
      if (!file_.next(ignored)) {
        return file_.error("the event record announces " + std::to_string(lines) + " lines, the file ends after " +
                           std::to_string(k) + " (truncated)");
      }
    }
    return std::nullopt;
  }

  TextFile file_;
  ObservationFile result_;
  char current_system_ = ' ';
  bool types_seen_ = false;
  std::size_t announced_types_ = 0;
};

// The file opened and its line 1 read.
core::Result<std::pair<TextFile, detail::ObservationVersion>> open_observations(const std::filesystem::path& path) {
  auto opened = TextFile::open(path, "RINEX observation file");
  if (!opened) return opened.error();
  TextFile file = std::move(opened).value();
  auto version = detail::read_observation_version(file);
  if (!version) return version.error();
  return std::pair<TextFile, detail::ObservationVersion>(std::move(file), std::move(version).value());
}

}  // namespace

core::Result<ObservationFile> detail::read_rinex3_observation_body(TextFile file, const ObservationVersion& version) {
  return ObservationReader(std::move(file), version.version).read();
}

core::Result<ObservationFile> read_rinex3_observations(const std::filesystem::path& path) {
  auto opened = open_observations(path);
  if (!opened) return opened.error();
  auto [file, version] = std::move(opened).value();
  if (version.version < 3.0 || version.version >= 4.0) return file.error("version " + version.text + " is not 3.x");
  return detail::read_rinex3_observation_body(std::move(file), version);
}

core::Result<ObservationFile> read_rinex_observations(const std::filesystem::path& path) {
  auto opened = open_observations(path);
  if (!opened) return opened.error();
  auto [file, version] = std::move(opened).value();
  if (version.version >= 2.0 && version.version < 3.0) return detail::read_rinex2_observation_body(std::move(file), version);
  if (version.version >= 3.0 && version.version < 4.0) return detail::read_rinex3_observation_body(std::move(file), version);
  return file.error("version " + version.text + " is not 2.x or 3.x: not a RINEX observation version read here");
}

ObservationEpoch to_observation_epoch(const GpsMeasurementEpoch& epoch, std::optional<double> receiver_clock_offset_s) {
  ObservationEpoch out;
  out.t = epoch.t;
  out.receiver_clock_offset_s = receiver_clock_offset_s;
  out.satellites.reserve(static_cast<std::size_t>(epoch.channel_count));
  for (int k = 0; k < epoch.channel_count; ++k) {
    const GpsChannelMeasurement& m = epoch.channels[static_cast<std::size_t>(k)];
    const int ssi = std::clamp(static_cast<int>(m.cn0_dbhz / 6.0), 1, 9);
    out.satellites.push_back({m.prn,
                              {{m.pseudorange_m, 0, ssi},
                               {m.carrier_phase_cycles, (m.loss_of_lock ? 1 : 0) | (m.half_cycle_ambiguity ? 2 : 0), ssi},
                               {m.doppler_hz, 0, ssi},
                               {m.cn0_dbhz, 0, ssi}}});
  }
  return out;
}

}  // namespace visors::gnss::files
