#include "visors/gnss/files/rinex_obs_common.hpp"

namespace visors::gnss::files::detail {

namespace {

constexpr std::size_t kFieldWidth = 14;  // F14.3

core::Result<core::GpsTime> first_observation(std::string_view line) {
  const std::string_view system = trim(column(line, 48, 3));
  if (!system.empty() && system != "GPS") {
    return core::Error{"TIME OF FIRST OBS", "time system '" + std::string(system) + "': only GPS is supported"};
  }
  // 5I6, F13.7 (RINEX 2.11 and 3.05 Table A1).
  static constexpr CalendarColumns kFirst{{2, 4}, {6, 6}, {12, 6}, {18, 6}, {24, 6}, {30, 13}};
  auto t = parse_gps_calendar(line, kFirst);
  if (!t) return core::Error{"TIME OF FIRST OBS", t.error().describe()};
  return t;
}

// APPROX POSITION XYZ and the antenna records: 3F14.4.
std::optional<core::Error> vector_record(const TextFile& file, std::string_view label, std::string_view line,
                                         ObservationHeader& h) {
  Eigen::Vector3d v;
  for (int k = 0; k < 3; ++k) {
    const auto value = parse_number(column(line, 14 * static_cast<std::size_t>(k), 14), std::string(label));
    if (!value) return file.error(value.error().describe());
    v(k) = value->value_or(0.0);
  }
  if (label == "APPROX POSITION XYZ") h.approx_position_m = v;
  if (label == "ANTENNA: DELTA H/E/N") h.antenna_delta_hen_m = v;
  if (label == "ANTENNA: DELTA X/Y/Z") h.antenna_delta_xyz_m = v;
  if (label == "ANTENNA: B.SIGHT XYZ") h.antenna_boresight_xyz = v;
  return std::nullopt;
}

std::string text(std::string_view line, std::size_t first, std::size_t width) {
  return std::string(trim(column(line, first, width)));
}

// "'<field>' is not <what>", built by appending (GCC 12 reports a false -Wrestrict on
// "'" + std::string(...)).
std::string not_a(std::string_view field, const char* what) {
  std::string message(1, '\'');
  message.append(field);
  message.append("' is not ");
  message.append(what);
  return message;
}

}  // namespace

core::Result<ObservationVersion> read_observation_version(TextFile& file) {
  std::string line;
  if (!file.next(line)) return file.file_error("empty file: not a RINEX observation file");
  if (trim(column(line, 60, 20)) != "RINEX VERSION / TYPE") {
    return file.error("the first line must be RINEX VERSION / TYPE");
  }
  const auto version = parse_number(column(line, 0, 9), "version (columns 1-9)");
  if (!version || !*version) return file.error("version (columns 1-9) is not a number");
  if (column(line, 20, 1) != "O") return file.error("file type (column 21) is not O (observation data)");
  const std::string_view system = column(line, 40, 1);
  return ObservationVersion{**version, text(line, 0, 9), system.empty() ? ' ' : system[0]};
}

std::optional<core::Error> read_common_header_record(const TextFile& file, std::string_view label,
                                                     std::string_view line, ObservationHeader& h) {
  if (label == "PGM / RUN BY / DATE") {
    h.program = text(line, 0, 20);
    h.run_by = text(line, 20, 20);
    h.creation_date = text(line, 40, 20);
  }
  if (label == "COMMENT") h.comments.emplace_back(trim(column(line, 0, 60)));
  if (label == "MARKER NAME") h.marker_name = text(line, 0, 60);
  if (label == "MARKER TYPE") h.marker_type = text(line, 0, 20);
  if (label == "OBSERVER / AGENCY") {
    h.observer = text(line, 0, 20);
    h.agency = text(line, 20, 40);
  }
  if (label == "REC # / TYPE / VERS") {
    h.receiver_number = text(line, 0, 20);
    h.receiver_type = text(line, 20, 20);
    h.receiver_version = text(line, 40, 20);
  }
  if (label == "ANT # / TYPE") {
    h.antenna_number = text(line, 0, 20);
    h.antenna_type = text(line, 20, 20);
  }
  if (label == "APPROX POSITION XYZ" || label == "ANTENNA: DELTA H/E/N" || label == "ANTENNA: DELTA X/Y/Z" ||
      label == "ANTENNA: B.SIGHT XYZ") {
    return vector_record(file, label, line, h);
  }
  if (label == "INTERVAL") {
    const auto value = parse_number(column(line, 0, 10), "INTERVAL (columns 1-10)");
    if (!value) return file.error(value.error().describe());
    h.interval_s = value->value_or(0.0);
  }
  if (label == "TIME OF FIRST OBS") {
    const auto t = first_observation(line);
    if (!t) return file.error(t.error().describe());
    h.first_observation = *t;
  }
  return std::nullopt;
}

core::Result<ObservationValue> parse_observation_field(std::string_view record, std::size_t first,
                                                       const std::string& type) {
  const std::string name = type + " (columns " + std::to_string(first + 1) + "-" + std::to_string(first + kFieldWidth) + ")";
  ObservationValue v;
  const auto value = parse_number(column(record, first, kFieldWidth), name);
  if (!value) return value.error();
  v.value = *value;
  const std::string_view lli = column(record, first + kFieldWidth, 1), ssi = column(record, first + kFieldWidth + 1, 1);
  v.lli = (lli.empty() || lli[0] == ' ') ? 0 : lli[0] - '0';
  v.ssi = (ssi.empty() || ssi[0] == ' ') ? 0 : ssi[0] - '0';
  if (v.lli < 0 || v.lli > 7) {
    return core::Error{type + " LLI (column " + std::to_string(first + kFieldWidth + 1) + ")",
                       not_a(lli, "a loss-of-lock indicator 0-7")};
  }
  if (v.ssi < 0 || v.ssi > 9) {
    return core::Error{type + " signal strength (column " + std::to_string(first + kFieldWidth + 2) + ")",
                       not_a(ssi, "a digit 0-9")};
  }
  return v;
}

}  // namespace visors::gnss::files::detail
