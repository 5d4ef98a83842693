#pragma once
// Ephemeris files of one spacecraft: a CSV table and a CCSDS Orbit Ephemeris Message (OEM, KVN
// form, CCSDS 502.0-B-3 "Orbit Data Messages", version 3.0 keywords compatible with 2.0 readers).
// Ground side (visors_dynamics_files), writers only.

#include <ostream>
#include <span>
#include <string>

#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"

namespace visors::dynamics::files {

struct EphemerisRecord {
  core::GpsTime t;
  core::StateVector x_gcrf;  // [m, m/s]
};

struct OemHeader {
  std::string object_name = "VISORS-DSC";
  std::string object_id = "UNKNOWN";  // international designator when known
  std::string originator = "visors_gnc";
  core::GpsTime creation;             // CREATION_DATE (UTC); the caller passes the wall clock
};

/// CSV with header `time_utc,t_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps` (GCRF; t_s from the first
/// record; UTC ISO time with microseconds). Full double precision (17 significant digits).
void write_ephemeris_csv(std::ostream& out, std::span<const EphemerisRecord> records);

/// OEM in KVN: REF_FRAME GCRF, CENTER_NAME EARTH, TIME_SYSTEM UTC, km and km/s with 1 mm / 1 um/s
/// resolution, epochs with microseconds. Precondition: at least one record.
void write_oem(std::ostream& out, std::span<const EphemerisRecord> records, const OemHeader& header);

}  // namespace visors::dynamics::files
