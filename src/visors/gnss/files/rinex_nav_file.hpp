#pragma once
// GPS navigation message files: RINEX 2.11 (IGS/RTCM, 2012 update, Table A3/A4: "N" files) and
// RINEX 3.00-3.05 (2020, section 6 and Table A6/A8: "N" files, GPS or mixed). Ground side.
//
// Both layouts carry per record an epoch line (PRN, t_oc, a_f0, a_f1, a_f2) and seven "broadcast
// orbit" lines of four 19-character numbers (D or E exponents). RINEX 2 starts the values at
// column 23 (orbit lines at column 4), RINEX 3 at column 24 (orbit lines at column 5). In mixed
// RINEX 3 files the records of other systems are skipped by their line count (GLONASS and SBAS
// 4 lines, the others 8). The header gives the ionosphere (RINEX 2 "ION ALPHA"/"ION BETA",
// RINEX 3 "IONOSPHERIC CORR" GPSA/GPSB) and the leap seconds.
//
// Conventions of the files handled here: the week in orbit line 5 is the continuous GPS week of
// t_oe; a two-digit RINEX 2 year yy is 19yy for yy >= 80, else 20yy; the fit interval (line 7) is
// in hours, and writers that store the ICD flag instead (0 or 1) mean 4 h or 6 h; a blank or
// 0.9999e9 transmission time means unknown (t_oe is used). Records are NOT screened here: build a
// gnss::EphemerisSet from them (it drops the unusable ones and says why).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <vector>

#include "visors/core/result.hpp"
#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/klobuchar.hpp"

namespace visors::gnss::files {

struct NavigationFile {
  double version = 0.0;                              // 2.11, 3.04, ...
  std::optional<KlobucharCoefficients> ionosphere;   // the header's GPS alpha/beta, when present
  std::optional<int> leap_seconds;                   // GPS - UTC [s], when present
  std::vector<BroadcastEphemeris> records;           // GPS records in file order
  std::vector<std::size_t> record_lines;             // line of each record's epoch line
};

/// Reads a RINEX 2.11 or 3.x GPS (or mixed) navigation file. Errors name "<path>:<line>" and the
/// field: unsupported version or file type, missing END OF HEADER, a truncated record, a value that
/// is not a number, a missing required value, an invalid epoch.
core::Result<NavigationFile> read_rinex_navigation(const std::filesystem::path& path);

/// Writes `file.records` as a RINEX 3.05 GPS navigation file (values in D19.12 with 'E'
/// exponents, the header's GPSA/GPSB and LEAP SECONDS when present), so simulated broadcast
/// ephemerides can be processed by other GNSS software; read back by read_rinex_navigation to the
/// 12 significant digits of the format. Error (the path) when the file cannot be written.
core::Result<bool> write_rinex3_navigation(const std::filesystem::path& path, const NavigationFile& file,
                                           const std::string& program);

}  // namespace visors::gnss::files
