// RINEX 2.10/2.11 observation files after their line 1 (read_rinex_observations). Layout after
// RINEX 2.11 (IGS/RTCM, 2012 update) Table A1 (header) and Table A2 (data records); columns below
// are 1-based as in the document.

#include <array>
#include <cctype>
#include <string>
#include <vector>

#include "visors/gnss/files/rinex_obs_common.hpp"
#include "visors/gnss/gps_constants.hpp"

namespace visors::gnss::files::detail {

namespace {

constexpr std::size_t kTypesPerLine = 9;        // # / TYPES OF OBSERV: I6, 9(4X,A2)
constexpr std::size_t kValuesPerLine = 5;       // observation records: 5(F14.3,I1,I1) = 80 columns
constexpr std::size_t kValueWidth = 16;
constexpr std::size_t kSatellitesPerLine = 12;  // epoch record: 12(A1,I2) in columns 33-68
constexpr std::size_t kWavelengthSatellites = 7;  // WAVELENGTH FACT L1/2: 7(3X,A1,I2)

// " yy mm dd hh mm ss.sssssss": 1X,I2.2,4(1X,I2),F11.7 (columns 2-3, 5-6, 8-9, 11-12, 14-15, 16-26).
constexpr CalendarColumns kEpoch{{1, 2}, {4, 2}, {7, 2}, {10, 2}, {13, 2}, {15, 11}, true};

std::string columns(std::size_t first, std::size_t width) {
  return "(columns " + std::to_string(first + 1) + "-" + std::to_string(first + width) + ")";
}

// A type list being read from "# / TYPES OF OBSERV" records.
struct TypeList {
  std::vector<std::string> codes;
  std::size_t announced = 0;  // 0: no record yet
};

struct SatelliteId {
  char system = 'G';  // a blank letter is GPS (RINEX 2.11 section 5.1)
  int number = 0;
};

// What an epoch or event line looks like where an observation line should be: columns 27-28
// blank, an epoch flag digit in column 29, a count in columns 30-32. An observation line has the
// decimal point of its second F14.3 value in column 27, or columns 17-30 blank.
bool looks_like_epoch_line(std::string_view line) {
  if (line.size() < 30 || line[26] != ' ' || line[27] != ' ' || line[28] < '0' || line[28] > '6') return false;
  const auto count = parse_integer(column(line, 29, 3), "");
  return count && count->has_value();
}

// A header without the writer's defaults: fields absent from the file stay empty (RINEX 2.11
// section 5.3: items not known are zero or blank, or their record is omitted).
ObservationHeader blank_header() {
  ObservationHeader h;
  for (std::string* field : {&h.program, &h.run_by, &h.marker_name, &h.marker_type, &h.observer, &h.agency,
                             &h.receiver_type, &h.antenna_type}) {
    field->clear();
  }
  h.observation_types.clear();
  h.interval_s = 0.0;
  return h;
}

class Rinex2Reader {
 public:
  Rinex2Reader(TextFile file, double version) : file_(std::move(file)) {
    result_.version = version;
    result_.header = blank_header();
  }

  core::Result<ObservationFile> read() {
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
    while (file_.next(line)) {
      const std::string_view label = trim(column(line, 60, 20));
      if (label == "END OF HEADER") return end_of_header();
      if (label == "# / TYPES OF OBSERV") {
        if (auto error = types_record(line, header_types_)) return error;
      } else if (label == "WAVELENGTH FACT L1/2") {
        if (auto error = wavelength_record(line)) return error;
      } else if (auto error = read_common_header_record(file_, label, line, result_.header)) {
        return error;
      }
    }
    return file_.error("the file ends here without an END OF HEADER line: the header is truncated");
  }

  std::optional<core::Error> end_of_header() {
    if (header_types_.announced == 0) return file_.error("no # / TYPES OF OBSERV record before END OF HEADER");
    if (header_types_.codes.size() != header_types_.announced) {
      return file_.error("# / TYPES OF OBSERV announces " + std::to_string(header_types_.announced) + " types, " +
                         std::to_string(header_types_.codes.size()) + " are listed");
    }
    result_.header.observation_types = header_types_.codes;
    lines_per_satellite_ = (header_types_.codes.size() + kValuesPerLine - 1) / kValuesPerLine;
    return std::nullopt;
  }

  // "     4    L1    C1    L2    P2": the count in columns 1-6 (blank on continuation lines), then
  // 9 codes of 6 columns, each right-aligned (4X,A2).
  std::optional<core::Error> types_record(std::string_view line, TypeList& list) const {
    const std::string_view count_field = column(line, 0, 6);
    if (!trim(count_field).empty()) {
      const auto count = parse_integer(count_field, "number of types (columns 1-6)");
      if (!count) return file_.error(count.error().describe());
      if (**count < 1) return file_.error("number of types (columns 1-6) must be at least 1");
      if (list.announced != 0) return file_.error("a second # / TYPES OF OBSERV record: the types are already declared");
      list.announced = static_cast<std::size_t>(**count);
    } else if (list.announced == 0) {
      return file_.error("# / TYPES OF OBSERV continuation line (columns 1-6 blank) without a first line");
    } else if (list.codes.size() >= list.announced) {
      return file_.error("# / TYPES OF OBSERV continuation line after all " + std::to_string(list.announced) +
                         " announced types");
    }
    for (std::size_t k = 0; k < kTypesPerLine && list.codes.size() < list.announced; ++k) {
      const std::string_view code = trim(column(line, 6 + 6 * k, 6));
      const std::string where = "observation type " + std::to_string(list.codes.size() + 1) + " " + columns(10 + 6 * k, 2);
      if (code.empty()) return file_.error(where + " is missing");
      if (code.size() != 2 || !std::isupper(static_cast<unsigned char>(code[0])) ||
          !std::isdigit(static_cast<unsigned char>(code[1]))) {
        return file_.error(where + ": '" + std::string(code) + "' is not a RINEX 2 code (a letter and a frequency digit)");
      }
      list.codes.emplace_back(code);
    }
    return std::nullopt;
  }

  // 2I6 (L1, L2 factors), I6 (number of satellites, blank or 0: the default record), 7(3X,A1,I2).
  std::optional<core::Error> wavelength_record(std::string_view line) {
    std::array<int, 2> factors{};
    for (std::size_t k = 0; k < 2; ++k) {
      const std::string name = std::string(k == 0 ? "L1" : "L2") + " wavelength factor " + columns(6 * k, 6);
      const auto factor = parse_integer(column(line, 6 * k, 6), name);
      if (!factor) return file_.error(factor.error().describe());
      if (!*factor || **factor < (k == 0 ? 1 : 0) || **factor > 2) {
        return file_.error(name + (k == 0 ? " must be 1 or 2" : " must be 0, 1 or 2"));
      }
      factors[k] = static_cast<int>(**factor);
    }
    const auto count = parse_integer(column(line, 12, 6), "number of satellites (columns 13-18)");
    if (!count) return file_.error(count.error().describe());
    const long long n = count->value_or(0);
    if (n == 0) {
      result_.header.wavelength_factors = factors;
      return std::nullopt;
    }
    if (n < 0 || n > static_cast<long long>(kWavelengthSatellites)) {
      return file_.error("number of satellites (columns 13-18) must be 0-7 on one WAVELENGTH FACT L1/2 record");
    }
    for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) {
      auto id = satellite_id(line, 21 + 6 * j, "wavelength factor satellite " + std::to_string(j + 1));
      if (!id) return id.error();
      if (id->system == 'G') result_.header.satellite_wavelength_factors[id->number] = factors;
    }
    return std::nullopt;
  }

  // A satellite "snn" at column `first` (0-based): system letter (blank: GPS), 2-digit number.
  core::Result<SatelliteId> satellite_id(std::string_view line, std::size_t first, const std::string& what) const {
    const std::string name = what + " " + columns(first, 3);
    const std::string_view letter = column(line, first, 1);
    const char system = letter.empty() || letter[0] == ' ' ? 'G' : letter[0];
    if (std::string_view("GRSECJI").find(system) == std::string_view::npos) {
      return file_.error(name + ": '" + std::string(1, system) + "' is not a satellite system (blank or G, R, S, E, C, J, I)");
    }
    const auto number = parse_integer(column(line, first + 1, 2), name);
    if (!number) return file_.error(number.error().describe());
    if (!*number) return file_.error(name + " is missing");
    if (**number < 1 || (system == 'G' && **number > kMaxGpsPrn)) {
      return file_.error(name + ": " + std::string(1, system) + std::to_string(**number) + " is not a satellite number" +
                         (system == 'G' ? " (GPS: 1..32)" : ""));
    }
    return SatelliteId{system, static_cast<int>(**number)};
  }

  // An epoch or event record starting at `line`: flag in column 29 (after 2 blank columns), the
  // number of satellites or special records in columns 30-32.
  std::optional<core::Error> read_record(const std::string& line) {
    const std::string_view flag_field = column(line, 28, 1);
    if (column(line, 26, 2) != "  " || flag_field.empty() || flag_field[0] < '0' || flag_field[0] > '6') {
      return file_.error("expected an epoch record: columns 27-28 blank and an epoch flag 0-6 in column 29, found '" +
                         std::string(column(line, 26, 3)) + "' in columns 27-29");
    }
    const int flag = flag_field[0] - '0';
    const auto count = parse_integer(column(line, 29, 3), "number of satellites (columns 30-32)");
    if (!count) return file_.error(count.error().describe());
    if (!*count || **count < 0) return file_.error("number of satellites / special records (columns 30-32) is missing");
    const auto n = static_cast<std::size_t>(**count);
    if (flag >= 2 && flag <= 5) return read_event(n);
    return read_epoch(line, flag, n);
  }

  // Flags 2-5: `n` special records (header records; the epoch may be blank). Read past, except a
  // new type list, which this file layout cannot hold (one list for all epochs).
  std::optional<core::Error> read_event(std::size_t n) {
    const std::size_t event_line = file_.line_number();
    TypeList types;
    std::string record;
    for (std::size_t k = 0; k < n; ++k) {
      if (!file_.next(record)) {
        return file_.error("the event record of line " + std::to_string(event_line) + " announces " +
                           std::to_string(n) + " special records, the file ends after " + std::to_string(k) + " (truncated)");
      }
      if (trim(column(record, 60, 20)) != "# / TYPES OF OBSERV") continue;
      if (auto error = types_record(record, types)) return error;
    }
    if (types.announced != 0 && types.codes != result_.header.observation_types) {
      return file_.error("the event record of line " + std::to_string(event_line) +
                         " changes the observation types (# / TYPES OF OBSERV): not supported, one type list per file");
    }
    return std::nullopt;
  }

  // Flags 0, 1 (kept) and 6 (cycle-slip records: same layout, read and dropped).
  std::optional<core::Error> read_epoch(const std::string& line, int flag, std::size_t n) {
    auto t = parse_gps_calendar(line, kEpoch);
    if (!t) return file_.error("epoch record: " + t.error().describe());
    const auto clock = parse_number(column(line, 68, 12), "receiver clock offset (columns 69-80)");
    if (!clock) return file_.error(clock.error().describe());
    auto satellites = satellite_list(line, n);
    if (!satellites) return satellites.error();
    ObservationEpoch epoch{*t, flag, *clock, {}};
    for (std::size_t k = 0; k < n; ++k) {
      auto values = observation_records((*satellites)[k], k, n);
      if (!values) return values.error();
      if ((*satellites)[k].system == 'G') epoch.satellites.push_back({(*satellites)[k].number, std::move(values).value()});
    }
    if (flag != 6) result_.epochs.push_back(std::move(epoch));
    return std::nullopt;
  }

  // 12 satellites on the epoch line (columns 33-68), the rest on continuation lines of 12 with
  // columns 1-32 blank (32X,12(A1,I2)).
  core::Result<std::vector<SatelliteId>> satellite_list(const std::string& epoch_line, std::size_t n) {
    std::vector<SatelliteId> ids;
    std::string continuation;
    const std::string* line = &epoch_line;
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0 && k % kSatellitesPerLine == 0) {
        if (!file_.next(continuation)) {
          return file_.error("the epoch announces " + std::to_string(n) + " satellites, the file ends after " +
                             std::to_string(k) + " of the list (truncated satellite list)");
        }
        if (!trim(column(continuation, 0, 32)).empty()) {
          return file_.error("the epoch announces " + std::to_string(n) + " satellites, " + std::to_string(k) +
                             " are listed: a continuation line must have columns 1-32 blank");
        }
        line = &continuation;
      }
      auto id = satellite_id(*line, 32 + 3 * (k % kSatellitesPerLine), "satellite " + std::to_string(k + 1));
      if (!id) return id.error();
      ids.push_back(*id);
    }
    return ids;
  }

  // The `lines_per_satellite_` lines of satellite `k` of `n`; values only for GPS satellites.
  core::Result<std::vector<ObservationValue>> observation_records(const SatelliteId& id, std::size_t k, std::size_t n) {
    const std::vector<std::string>& types = result_.header.observation_types;
    const std::string name = std::string(1, id.system) + (id.number < 10 ? "0" : "") + std::to_string(id.number);
    std::vector<ObservationValue> values;
    std::string record;
    for (std::size_t row = 0; row < lines_per_satellite_; ++row) {
      const bool ended = !file_.next(record);
      if (ended || looks_like_epoch_line(record)) {
        return file_.error("the epoch announces " + std::to_string(n) + " satellites, " +
                           (ended ? "the file ends" : "an epoch record starts") + " in the records of satellite " +
                           std::to_string(k + 1) + " (" + name + "): truncated epoch");
      }
      if (id.system != 'G') continue;
      for (std::size_t m = 0; m < kValuesPerLine && kValuesPerLine * row + m < types.size(); ++m) {
        auto value = parse_observation_field(record, kValueWidth * m, types[kValuesPerLine * row + m]);
        if (!value) return file_.error(name + " " + value.error().describe());
        ObservationValue v = *value;
        if (v.value && *v.value == 0.0) v.value.reset();  // "written as 0.0 or blanks" (Table A2)
        values.push_back(v);
      }
    }
    return values;
  }

  TextFile file_;
  ObservationFile result_;
  TypeList header_types_;
  std::size_t lines_per_satellite_ = 1;
};

}  // namespace

core::Result<ObservationFile> read_rinex2_observation_body(TextFile file, const ObservationVersion& version) {
  if (version.system != ' ' && version.system != 'G' && version.system != 'M') {
    return file.error("satellite system (column 41) '" + std::string(1, version.system) +
                      "' is not GPS (blank or G) or mixed (M): the file holds no GPS records");
  }
  return Rinex2Reader(std::move(file), version.version).read();
}

}  // namespace visors::gnss::files::detail
