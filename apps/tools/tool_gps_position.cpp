// `visors tool gps-position`: a GPS satellite's position, velocity and clock from a broadcast
// navigation file (RINEX 2.11 or 3.x), with the file's records screened (gnss/ephemeris_set.hpp).
//   {"nav": "PATH", "prn": n, "gps_time": "YYYY-MM-DDTHH:MM:SS"}
//   -> {"r_ecef": [3] m, "v_ecef": [3] m/s, "clock_bias": s, "tgd": s, "iode": n, "toe": "..."}
// clock_bias is the satellite clock offset including the relativistic term, without T_GD (an L1
// C/A user subtracts tgd). PATH is found through the data search path when it is relative.

#include <string>

#include "visors/core/files/data_path.hpp"
#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/ephemeris_set.hpp"
#include "visors/gnss/files/rinex_nav_file.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

std::string no_record_message(const gnss::EphemerisSet& set, int prn, core::GpsTime t) {
  int records = 0;
  std::string reasons;
  for (const auto& r : set.records()) {
    if (r.ephemeris.prn != prn) continue;
    ++records;
    if (r.status != gnss::RecordStatus::kUsable && gnss::within_fit_interval(r.ephemeris, t) && reasons.size() < 400) {
      reasons += std::string("; line ") + std::to_string(r.source_line) + " " + gnss::to_string(r.status) + ": " + r.reason;
    }
  }
  return "no usable record of PRN " + std::to_string(prn) + " at " + t.format(core::TimeScale::kGps, 0) + " (" +
         std::to_string(records) + " records in the file" + reasons + ")";
}

Json run_gps_position(const Json& in) {
  reject_unknown_keys(in, {"nav", "prn", "gps_time"});
  const std::string nav_name = require_string(in, "nav");
  const double prn_value = require_number(in, "prn");
  if (prn_value != static_cast<int>(prn_value) || prn_value < 1 || prn_value > 32) {
    throw ToolInputError("prn", "must be an integer in 1..32");
  }
  const int prn = static_cast<int>(prn_value);
  const core::GpsTime t = take(core::GpsTime::parse(require_string(in, "gps_time"), core::TimeScale::kGps), "gps_time");
  const auto path = core::files::find_data_file(nav_name);
  if (!path) throw ToolInputError("nav", "'" + nav_name + "' not found (nor in the data search path)");
  const gnss::files::NavigationFile nav = take(gnss::files::read_rinex_navigation(*path), "nav");
  const auto set = gnss::EphemerisSet::screen(nav.records, nav.record_lines);
  const gnss::BroadcastEphemeris* eph = set.select(prn, t);
  if (eph == nullptr) throw ToolInputError("prn", no_record_message(set, prn, t));
  const gnss::GpsSatelliteState s = gnss::broadcast_state(*eph, t);
  return Json{{"r_ecef", to_json(s.r_ecef_m)},
              {"v_ecef", to_json(s.v_ecef_mps)},
              {"clock_bias", s.clock_bias_s},
              {"tgd", eph->tgd_s},
              {"iode", eph->iode},
              {"toe", eph->toe.format(core::TimeScale::kGps, 0)}};
}

const bool registered = register_tool(
    {"gps-position",
     "GPS satellite state from a RINEX navigation file {nav, prn, gps_time} -> r_ecef, v_ecef, clock_bias, tgd, iode",
     run_gps_position});

}  // namespace
}  // namespace visors::tools
