#pragma once
// RINEX 3 observation files, GPS only (RINEX 3.05, IGS/RINEX WG and RTCM-SC104, December 2020:
// section 5 "RINEX observation files", Appendix Table A1 "GNSS observation data file - header
// section description" (labels in columns 61-80) and Table A2 "GNSS observation data file - data
// record description": the epoch record "> yyyy mm dd hh mm ss.sssssss  f nnn      clock" and the
// observation records "Gnn" + per type F14.3, LLI (I1), signal strength (I1)). Ground side: the
// simulator writes its receivers' measurements here, epoch by epoch, so any GNSS software can
// process them, and the reader brings them back (round trip tested).
//
// Units of the values are RINEX's: pseudorange (C) m, carrier phase (L) cycles, Doppler (D) Hz,
// signal strength (S) dB-Hz. A value that does not fit F14.3 (|v| >= 1e10, or <= -1e9 where the
// sign takes a column) is an error naming the epoch, satellite and type, never a shifted field.
// LLI (0-7) bit 0 (value 1) = loss of lock since the previous epoch: a possible cycle slip.
// Epoch times are written to the format's 0.1 us (rounded), read back exactly.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/files/output_file.hpp"
#include "core/gps_time.hpp"
#include "core/status.hpp"
#include "gnss/gps_measurement.hpp"

namespace visors::gnss::files {

struct ObservationHeader {
  std::string program = "visors";  // PGM / RUN BY / DATE
  std::string run_by = "visors";
  std::string creation_date;       // "yyyymmdd hhmmss UTC"; empty: the writer uses the current UTC time
  std::string marker_name = "VISORS";
  std::string marker_type = "SPACEBORNE";  // RINEX 3.05 MARKER TYPE for an orbiting receiver
  std::string observer = "visors";
  std::string agency = "visors";
  std::string receiver_number, receiver_type = "SIMULATED", receiver_version;
  std::string antenna_number, antenna_type = "SIMULATED";
  Eigen::Vector3d approx_position_m = Eigen::Vector3d::Zero();    // APPROX POSITION XYZ [m]
  Eigen::Vector3d antenna_delta_hen_m = Eigen::Vector3d::Zero();  // ANTENNA: DELTA H/E/N [m]
  /// Vehicle receivers (RINEX 3.05 Table A1): the antenna reference point and the boresight in
  /// the body frame, "ANTENNA: DELTA X/Y/Z" [m] and "ANTENNA: B.SIGHT XYZ" (unit).
  std::optional<Eigen::Vector3d> antenna_delta_xyz_m;
  std::optional<Eigen::Vector3d> antenna_boresight_xyz;
  std::vector<std::string> observation_types = {"C1C", "L1C", "D1C", "S1C"};
  double interval_s = 1.0;  // INTERVAL [s]; written when > 0
  core::GpsTime first_observation;
  std::vector<std::string> comments;
};

struct ObservationValue {
  std::optional<double> value;
  int lli = 0;  // loss-of-lock indicator 0-7 (blank = 0); bit 0: loss of lock / possible cycle slip
  int ssi = 0;  // signal strength indicator 1-9, 0 = unknown (blank)
};

struct SatelliteObservations {
  int prn = 0;
  std::vector<ObservationValue> values;  // one per header observation type, in that order
};

struct ObservationEpoch {
  core::GpsTime t;  // receiver time tag (GPS time scale)
  int flag = 0;     // 0 OK, 1 power failure since the previous epoch
  std::optional<double> receiver_clock_offset_s;  // must fit F15.12: -10 s < offset < 100 s
  std::vector<SatelliteObservations> satellites;
};

struct ObservationFile {
  double version = 3.05;
  ObservationHeader header;
  std::vector<ObservationEpoch> epochs;
};

/// Writes epoch by epoch (a simulator need not keep a day of data in memory).
class Rinex3ObservationWriter {
 public:
  /// Creates the file and writes the header (more than 13 types go on continuation lines).
  /// Errors: the path; no types, a type that is not a 3-character code, INTERVAL or a header
  /// vector that does not fit its field.
  static core::Result<Rinex3ObservationWriter> open(const std::filesystem::path& path, const ObservationHeader& header);
  /// Errors name the epoch ("epoch <iso>"), satellite (".Gnn") and type (".L1C"): a PRN outside
  /// 1..32, a value count that differs from the header's types, a value that does not fit F14.3,
  /// LLI outside 0..7, SSI outside 0..9, flag outside 0..1, a clock offset that does not fit
  /// F15.12; nothing of a rejected epoch is written. Error after close().
  core::Result<bool> write(const ObservationEpoch& epoch);
  /// Flushes and closes; Error (the path) when the data could not be written.
  core::Result<bool> close();

 private:
  Rinex3ObservationWriter(std::filesystem::path path, core::files::OutputFile file, std::vector<std::string> types)
      : path_(std::move(path)), file_(std::move(file)), types_names_(std::move(types)), types_(types_names_.size()) {}
  std::filesystem::path path_;
  core::files::OutputFile file_;
  std::vector<std::string> types_names_;  // the header's observation types, for error fields
  std::size_t types_ = 0;
};

/// Writes a whole file (header + epochs); the errors of the writer.
core::Result<bool> write_rinex3_observations(const std::filesystem::path& path, const ObservationHeader& header,
                                             std::span<const ObservationEpoch> epochs);
core::Result<bool> write_rinex3_observations(const std::filesystem::path& path, const ObservationFile& file);

/// Reads a RINEX 3.0x observation file: GPS records (other systems' records skipped), epochs with
/// flags 0 and 1; event records (flags 2-5: their special records) and cycle-slip records (flag 6)
/// are read past. Errors have field "<path>:<line>" and a message naming the field (columns) and
/// the problem: version not 3.x or type not O, no END OF HEADER (the last line), no or too few
/// GPS observation types, a malformed epoch line, fewer satellite lines than the epoch announces
/// (end of file or the next '>' record), a non-numeric value, LLI/SSI not a digit.
core::Result<ObservationFile> read_rinex3_observations(const std::filesystem::path& path);

/// The receiver's measurement record as a RINEX epoch with the types C1C, L1C, D1C, S1C (LLI 1 on
/// L1C after a loss of lock; SSI from C/N0 by the RINEX 3.0x signal-strength
/// mapping 1: < 12 dB-Hz, 2: 12-17, ..., 7: 42-47, 8: 48-53, 9: >= 54, i.e. min(9, max(1, C/N0 / 6))).
ObservationEpoch to_observation_epoch(const GpsMeasurementEpoch& epoch, std::optional<double> receiver_clock_offset_s = {});

}  // namespace visors::gnss::files
