#pragma once
// RINEX 3 observation files, GPS only (RINEX 3.05, IGS/RTCM-SC104 2020: section 5 and Tables A1-A3
// for the header labels, the epoch record "> yyyy mm dd hh mm ss.sssssss  f nn" and the
// observation records "Gnn" + per type F14.3, LLI (I1), signal strength (I1)). Ground side: the
// simulator writes its receivers' measurements here so any GNSS software can process them, and
// the reader brings them back (round trip tested).
//
// Units of the values are RINEX's: pseudorange (C) m, carrier phase (L) cycles, Doppler (D) Hz,
// signal strength (S) dB-Hz. A value too large for F14.3 (|v| >= 1e10) is an error, not a
// truncated field. LLI bit 0 (value 1) = loss of lock since the previous epoch: a new ambiguity.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/gps_time.hpp"
#include "core/status.hpp"
#include "gnss/gps_measurement.hpp"

namespace visors::gnss::files {

struct ObservationHeader {
  std::string program = "visors";
  std::string marker_name = "VISORS";
  std::string marker_type = "SPACEBORNE";  // RINEX 3.05 Table A2: a receiver on a spacecraft
  std::string observer = "visors";
  std::string agency = "visors";
  std::string receiver_number, receiver_type = "SIMULATED", receiver_version;
  std::string antenna_number, antenna_type = "SIMULATED";
  Eigen::Vector3d approx_position_m = Eigen::Vector3d::Zero();    // APPROX POSITION XYZ [m]
  Eigen::Vector3d antenna_delta_hen_m = Eigen::Vector3d::Zero();  // ANTENNA: DELTA H/E/N [m]
  /// Vehicle receivers (RINEX 3.05 Table A2): the antenna reference point and the boresight in
  /// the body frame, "ANTENNA: DELTA X/Y/Z" [m] and "ANTENNA: B.SIGHT XYZ" (unit).
  std::optional<Eigen::Vector3d> antenna_delta_xyz_m;
  std::optional<Eigen::Vector3d> antenna_boresight_xyz;
  std::vector<std::string> observation_types = {"C1C", "L1C", "D1C", "S1C"};
  double interval_s = 1.0;
  core::GpsTime first_observation;
  std::vector<std::string> comments;
};

struct ObservationValue {
  std::optional<double> value;
  int lli = 0;  // loss-of-lock indicator, 0-7
  int ssi = 0;  // signal strength indicator, 0 (unknown) or 1-9
};

struct SatelliteObservations {
  int prn = 0;
  std::vector<ObservationValue> values;  // one per header observation type, in that order
};

struct ObservationEpoch {
  core::GpsTime t;  // receiver time tag (GPS time scale)
  int flag = 0;     // 0 OK, 1 power failure since the previous epoch
  std::optional<double> receiver_clock_offset_s;
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
  /// Creates the file and writes the header. Errors: the path; an observation type that is not a
  /// 3-character code, more than 13 types.
  static core::Result<Rinex3ObservationWriter> open(const std::filesystem::path& path, const ObservationHeader& header);
  /// Errors name the epoch and satellite: a PRN outside 1..32, a value count that differs from
  /// the header's types, a value that does not fit F14.3, LLI/SSI outside 0..9, flag outside 0..1.
  core::Result<bool> write(const ObservationEpoch& epoch);
  /// Flushes and closes; Error (the path) when the data could not be written.
  core::Result<bool> close();

 private:
  struct FileCloser {
    void operator()(std::FILE* f) const {
      if (f != nullptr) std::fclose(f);
    }
  };
  Rinex3ObservationWriter(std::filesystem::path path, std::FILE* file, std::size_t types)
      : path_(std::move(path)), file_(file), types_(types) {}
  std::filesystem::path path_;
  std::unique_ptr<std::FILE, FileCloser> file_;
  std::size_t types_ = 0;
};

/// Writes a whole file (header + epochs).
core::Result<bool> write_rinex3_observations(const std::filesystem::path& path, const ObservationFile& file);

/// Reads a RINEX 3.0x observation file: GPS records (other systems skipped), epochs with flags 0
/// and 1; event records (flags 2-5) and cycle-slip records (flag 6) are read past. Errors name
/// "<path>:<line>" and the field: version not 3.x, no END OF HEADER, no GPS observation types, a
/// malformed epoch line, fewer satellite lines than the epoch announces, a non-numeric value.
core::Result<ObservationFile> read_rinex3_observations(const std::filesystem::path& path);

/// The receiver's measurement record as a RINEX epoch with the types C1C, L1C, D1C, S1C (LLI 1 on
/// L1C after a loss of lock; SSI from C/N0 by RINEX 3.05 Table 10: min(9, max(1, C/N0 / 6))).
ObservationEpoch to_observation_epoch(const GpsMeasurementEpoch& epoch, std::optional<double> receiver_clock_offset_s = {});

}  // namespace visors::gnss::files
