// `visors tool frame`: one state between GCRF and ITRF (full IAU 2006/2000A chain, ERFA).
//
// Input:  {"utc": "YYYY-MM-DDTHH:MM:SS[.fff]",
//          "r_itrf": [m], "v_itrf": [m/s]      -> output {"r_gcrf", "v_gcrf"}
//       or "r_gcrf": [m], "v_gcrf": [m/s]      -> output {"r_itrf", "v_itrf"},
//          optional "eop": {"xp", "yp", "dx", "dy": arcsec, "dut1", "lod": s} (absent keys are 0)
//          or "eop_file": a finals2000A file (found through VISORS_DATA_PATH), interpolated at utc}
// Without eop/eop_file every EOP is zero (UT1 = UTC, no polar motion): ~0.5 km error at LEO.

#include <cmath>
#include <optional>
#include <string>

#include <fmt/core.h>

#include "visors/core/constants.hpp"
#include "visors/core/earth_frames.hpp"
#include "visors/core/eop.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/core/files/eop_file.hpp"
#include "visors/core/gps_time.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

using core::EarthOrientation;
using core::GpsTime;

// Reads an optional eop member; rejects values no real EOP can take (a unit mix-up, e.g. mas
// for arcsec or ms for s, must not pass silently).
double eop_value(const Json& eop, const std::string& key, double limit, const std::string& unit) {
  const double value = optional_number(eop, key, "eop").value_or(0.0);
  if (std::abs(value) > limit) {
    throw ToolInputError("eop." + key,
                         fmt::format("must be within +-{:g} {} (is the unit right?)", limit, unit));
  }
  return value;
}

EarthOrientation read_eop(const Json& in, GpsTime t) {
  const bool explicit_eop = in.contains("eop");
  const bool from_file = in.contains("eop_file");
  if (explicit_eop && from_file) {
    throw ToolInputError("eop_file", "give either eop or eop_file, not both");
  }
  EarthOrientation eop;
  if (explicit_eop) {
    const Json& e = require_object(in, "eop");
    reject_unknown_keys(e, {"xp", "yp", "dut1", "lod", "dx", "dy"}, "eop");
    eop.xp = eop_value(e, "xp", 5.0, "arcsec") * core::kArcsecToRad;
    eop.yp = eop_value(e, "yp", 5.0, "arcsec") * core::kArcsecToRad;
    eop.dut1 = eop_value(e, "dut1", 1.0, "s");
    eop.lod = eop_value(e, "lod", 0.01, "s");
    eop.dx = eop_value(e, "dx", 0.1, "arcsec") * core::kArcsecToRad;
    eop.dy = eop_value(e, "dy", 0.1, "arcsec") * core::kArcsecToRad;
  } else if (from_file) {
    const std::string name = require_string(in, "eop_file");
    const auto path = core::files::find_data_file(name);
    if (!path) {
      throw ToolInputError("eop_file", "'" + name +
                                           "' not found (searched VISORS_DATA_PATH and the "
                                           "repository's data/ folder)");
    }
    const auto table = take(core::files::read_eop_file(*path), "eop_file");
    const auto at = table.at(t);
    if (!at.ok()) throw ToolInputError("utc", at.error().message);
    eop = at.value();
  }
  return eop;
}

Json run_frame(const Json& in) {
  reject_unknown_keys(in, {"utc", "r_itrf", "v_itrf", "r_gcrf", "v_gcrf", "eop", "eop_file"});
  const GpsTime t = take(GpsTime::parse(require_string(in, "utc"), core::TimeScale::kUtc), "utc");

  const bool itrf_given = in.contains("r_itrf") || in.contains("v_itrf");
  const bool gcrf_given = in.contains("r_gcrf") || in.contains("v_gcrf");
  if (itrf_given && gcrf_given) {
    throw ToolInputError(in.contains("r_gcrf") ? "r_gcrf" : "v_gcrf",
                         "cannot be combined with r_itrf/v_itrf: give exactly one of the pairs "
                         "(r_itrf, v_itrf) or (r_gcrf, v_gcrf)");
  }
  if (!itrf_given && !gcrf_given) {
    throw ToolInputError("r_itrf", "is required (or r_gcrf): give exactly one of the pairs "
                                   "(r_itrf, v_itrf) or (r_gcrf, v_gcrf)");
  }
  const EarthOrientation eop = read_eop(in, t);
  if (itrf_given) {
    const core::StateVector itrf{require_vector3(in, "r_itrf"), require_vector3(in, "v_itrf")};
    const core::StateVector gcrf = core::itrf_to_gcrf(t, itrf, eop);
    return Json{{"r_gcrf", to_json(gcrf.r)}, {"v_gcrf", to_json(gcrf.v)}};
  }
  const core::StateVector gcrf{require_vector3(in, "r_gcrf"), require_vector3(in, "v_gcrf")};
  const core::StateVector itrf = core::gcrf_to_itrf(t, gcrf, eop);
  return Json{{"r_itrf", to_json(itrf.r)}, {"v_itrf", to_json(itrf.v)}};
}

[[maybe_unused]] const bool kRegistered = register_tool(
    {"frame", "GCRF <-> ITRF state at a UTC time (IAU 2006/2000A, optional EOP)", run_frame});

}  // namespace
}  // namespace visors::tools
