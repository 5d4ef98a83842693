#include "visors/dynamics/files/ephemeris_file.hpp"

#include <cassert>
#include <cstdio>

namespace visors::dynamics::files {
namespace {

constexpr int kEpochDecimals = 6;  // 1 us: 7.6 mm along-track at LEO

std::string utc(core::GpsTime t) { return t.format(core::TimeScale::kUtc, kEpochDecimals); }

}  // namespace

void write_ephemeris_csv(std::ostream& out, std::span<const EphemerisRecord> records) {
  out << "time_utc,t_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps\n";
  if (records.empty()) return;
  const core::GpsTime t0 = records.front().t;
  char line[320];
  for (const EphemerisRecord& rec : records) {
    const auto& r = rec.x_gcrf.r;
    const auto& v = rec.x_gcrf.v;
    std::snprintf(line, sizeof line, ",%.9f,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", rec.t.seconds_since(t0),
                  r.x(), r.y(), r.z(), v.x(), v.y(), v.z());
    out << utc(rec.t) << line;
  }
}

void write_oem(std::ostream& out, std::span<const EphemerisRecord> records, const OemHeader& header) {
  assert(!records.empty());
  out << "CCSDS_OEM_VERS = 2.0\n"
      << "CREATION_DATE = " << header.creation.format(core::TimeScale::kUtc, 0) << "\n"
      << "ORIGINATOR = " << header.originator << "\n\n"
      << "META_START\n"
      << "OBJECT_NAME = " << header.object_name << "\n"
      << "OBJECT_ID = " << header.object_id << "\n"
      << "CENTER_NAME = EARTH\n"
      << "REF_FRAME = GCRF\n"
      << "TIME_SYSTEM = UTC\n"
      << "START_TIME = " << utc(records.front().t) << "\n"
      << "STOP_TIME = " << utc(records.back().t) << "\n"
      << "META_STOP\n\n";
  char line[256];
  for (const EphemerisRecord& rec : records) {
    const Eigen::Vector3d r_km = rec.x_gcrf.r * 1e-3;
    const Eigen::Vector3d v_km_s = rec.x_gcrf.v * 1e-3;
    std::snprintf(line, sizeof line, " %.6f %.6f %.6f %.9f %.9f %.9f\n", r_km.x(), r_km.y(), r_km.z(),
                  v_km_s.x(), v_km_s.y(), v_km_s.z());
    out << utc(rec.t) << line;
  }
}

}  // namespace visors::dynamics::files
