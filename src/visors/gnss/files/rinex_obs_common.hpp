#pragma once
// Internal to visors_gnss_files (not for users of the library): what the RINEX 2 and RINEX 3
// observation readers share. Both versions start with the same RINEX VERSION / TYPE line (format
// version F9.2 in columns 1-9, file type 'O' in column 21, satellite system in column 41), give
// the station records the same columns (PGM / RUN BY / DATE 3A20, MARKER NAME A60, OBSERVER /
// AGENCY A20,A40, REC # / TYPE / VERS 3A20, ANT # / TYPE 2A20, the position and antenna vectors
// 3F14.4, INTERVAL F10.3, TIME OF FIRST OBS 5I6,F13.7,5X,A3: RINEX 2.11 Table A1 and RINEX 3.05
// Table A1), and write one observation as F14.3 + LLI (I1) + signal strength (I1) (RINEX 2.11
// Table A2, RINEX 3.05 Table A2). The public readers are in rinex_obs_file.hpp.

#include <cstddef>
#include <string>
#include <string_view>

#include "visors/core/result.hpp"
#include "visors/gnss/files/rinex_obs_file.hpp"
#include "visors/gnss/files/text_file.hpp"

namespace visors::gnss::files::detail {

struct ObservationVersion {
  double version = 0.0;
  std::string text;  // the version as written (columns 1-9, trimmed), for messages
  char system = ' '; // satellite system (column 41): blank, G, R, S, E, C, J, I or M
};

/// Reads line 1 of an observation file. Errors: an empty file (field "<path>"), otherwise at line
/// 1: not the RINEX VERSION / TYPE label, a version that is not a number, a file type that is
/// not O. The caller checks the version range.
core::Result<ObservationVersion> read_observation_version(TextFile& file);

/// Reads `line` into `header` when `label` is one of the records both versions share; any other
/// label is left alone (the caller handles its version's own records, unknown ones are skipped
/// as RINEX 2.11 section 6.9 recommends). Errors at the current line of `file`: a vector or
/// INTERVAL that is not a number, a TIME OF FIRST OBS that is not a valid GPS-time epoch.
std::optional<core::Error> read_common_header_record(const TextFile& file, std::string_view label,
                                                     std::string_view line, ObservationHeader& header);

/// One observation field of `record`: the value in columns [first, first + 14) (0-based; blank:
/// absent), the LLI in the next column (blank: 0; a digit 0-7) and the signal strength in the one
/// after (blank: 0; a digit 0-9). Errors name `type` and the 1-based columns ("L1 (columns 1-14)",
/// "L1 LLI (column 15)").
core::Result<ObservationValue> parse_observation_field(std::string_view record, std::size_t first,
                                                       const std::string& type);

/// The rest of a RINEX 2.x file after its line 1 (rinex2_obs_reader.cpp).
core::Result<ObservationFile> read_rinex2_observation_body(TextFile file, const ObservationVersion& version);
/// The rest of a RINEX 3.x file after its line 1 (rinex_obs_file.cpp).
core::Result<ObservationFile> read_rinex3_observation_body(TextFile file, const ObservationVersion& version);

}  // namespace visors::gnss::files::detail
