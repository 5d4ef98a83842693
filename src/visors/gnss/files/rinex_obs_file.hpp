#pragma once
// RINEX observation files, GPS only. Written as RINEX 3.05 (IGS/RINEX WG and RTCM-SC104,
// December 2020: section 5 "RINEX observation files", Appendix Table A1 "GNSS observation data
// file - header section description" (labels in columns 61-80) and Table A2 "GNSS observation
// data file - data record description": the epoch record "> yyyy mm dd hh mm ss.sssssss  f nnn
// clock" and the observation records "Gnn" + per type F14.3, LLI (I1), signal strength (I1)).
// Read as RINEX 3.0x or as RINEX 2.10/2.11 (W. Gurtner, L. Estey, "RINEX: The Receiver
// Independent Exchange Format Version 2.11", IGS/RTCM, 2012 update: Table A1 "GNSS observation
// data file - header section description", Table A2 "GNSS observation data file - data record
// description": the epoch record " yy mm dd hh mm ss.sssssss  f nnn" + up to 12 satellites
// "Gnn" in columns 33-68 (continuation lines from column 33) + clock offset F12.9 in columns
// 69-80, then per satellite the values 5 to a line, each F14.3 + LLI + signal strength).
// Ground side: the simulator writes its receivers' measurements here, epoch by epoch, so any
// GNSS software can process them, and the reader brings them back (round trip tested); real
// receiver files (RINEX 2 from station networks, RINEX 3) come in through the same structs.
//
// Units of the values are RINEX's: pseudorange (C, RINEX 2 also P) m, carrier phase (L) cycles,
// Doppler (D) Hz, signal strength (S) dB-Hz (RINEX 2: receiver-dependent). A value that does not
// fit F14.3 (|v| >= 1e10, or <= -1e9 where the sign takes a column) is a write error naming the
// epoch, satellite and type, never a shifted field. LLI (0-7) bit 0 (value 1) = loss of lock
// since the previous epoch: a possible cycle slip; RINEX 2 bit 1: the opposite of the
// satellite's wavelength factor at this epoch; bit 2: observed under anti-spoofing.
// Epoch times are written to the format's 0.1 us (rounded), read back exactly.

#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "visors/core/files/output_file.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/gps_measurement.hpp"

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
  /// RINEX 3 codes ("C1C"); read from a RINEX 2 file, its 2-character codes as written ("L1",
  /// "C1", "P2"; rinex2_gps_observation_code in rinex_obs_codes.hpp gives their RINEX 3 codes).
  std::vector<std::string> observation_types = {"C1C", "L1C", "D1C", "S1C"};
  double interval_s = 1.0;  // INTERVAL [s]; written when > 0; a RINEX 2 file without it: 0
  core::GpsTime first_observation;
  std::vector<std::string> comments;
  /// RINEX 2 "WAVELENGTH FACT L1/2" (RINEX 2.11 Table A1 and section 10.1.2): the factor the GPS
  /// L1 and L2 carrier wavelengths are divided by for ambiguity resolution: 1 full-cycle
  /// ambiguities, 2 half-cycle (squaring receivers), 0 on L2 a single-frequency receiver. The
  /// default record, then the satellite-specific records (GPS PRN -> {L1, L2}); LLI bit 1 flips
  /// a satellite's factor for one epoch. RINEX 3 has no such record (not written): {1, 1}.
  std::array<int, 2> wavelength_factors = {1, 1};
  std::map<int, std::array<int, 2>> satellite_wavelength_factors;
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
  std::optional<double> receiver_clock_offset_s;  // written F15.12: -10 s < offset < 100 s (RINEX 2: F12.9)
  std::vector<SatelliteObservations> satellites;
};

struct ObservationFile {
  double version = 3.05;  // as read: 2.10, 2.11, 3.04, ...
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

/// Reads a RINEX 2.10/2.11 or 3.0x observation file (the version of line 1 decides), GPS records
/// only (other systems' records read past); epochs with flags 0 and 1 are kept, event records
/// (flags 2-5: their special records) and cycle-slip records (flag 6) are read past. Errors have
/// field "<path>:<line>" (the whole path for an empty or missing file) and a message naming the
/// field (columns) and the problem: version not 2.x or 3.x or type not O, no END OF HEADER (the
/// last line), no (or too few) GPS observation types, a malformed epoch line, fewer lines than
/// an epoch or event announces (end of file, or the next epoch record where a satellite's
/// record should be), a non-numeric value, LLI/SSI not a digit.
///
/// RINEX 2 specifics (RINEX 2.11 Tables A1/A2): `version` 2.10/2.11, `header.observation_types`
/// the 2-character codes as written; a blank satellite system letter is GPS; two-digit years
/// 80-99 are 19yy, 00-79 20yy (section 6.5); an observation written as 0.0 is absent like a
/// blank one ("Missing observations are written as 0.0 or blanks", Table A2); the satellite
/// system of line 1 (column 41) must be blank, G or M (a file of another system holds no GPS
/// records: an error); the time system of TIME OF FIRST OBS must be GPS or blank (taken as GPS,
/// the default of pure GPS files; mixed files must name it); a "# / TYPES OF OBSERV" record
/// inside an event (flags 2-5) that changes the types is an error (one type list per file;
/// other header records inside events are read past). Fields absent from the file stay empty
/// (no writer defaults).
core::Result<ObservationFile> read_rinex_observations(const std::filesystem::path& path);

/// As read_rinex_observations for RINEX 3.0x only: any other version is an error at line 1
/// ("version 2.11 is not 3.x"). Fields absent from the file keep ObservationHeader's defaults.
core::Result<ObservationFile> read_rinex3_observations(const std::filesystem::path& path);

/// The receiver's measurement record as a RINEX epoch with the types C1C, L1C, D1C, S1C (LLI 1 on
/// L1C after a loss of lock; SSI from C/N0 by the RINEX 3.0x signal-strength
/// mapping 1: < 12 dB-Hz, 2: 12-17, ..., 7: 42-47, 8: 48-53, 9: >= 54, i.e. min(9, max(1, C/N0 / 6))).
ObservationEpoch to_observation_epoch(const GpsMeasurementEpoch& epoch, std::optional<double> receiver_clock_offset_s = {});

}  // namespace visors::gnss::files
