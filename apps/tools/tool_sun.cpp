// `visors tool sun`: the apparent Sun seen from a spacecraft (astro/apparent_sun.hpp, the flight
// software's implementation).
//   {"time": "YYYY-MM-DDTHH:MM:SS[.fff]" (UTC), "r_gcrf": [m], "v_gcrf": [m/s],
//    "target_offset_arcsec"?: [xi east, eta north]}
//     -> {"apparent_unit_gcrf": [3], "geometric_unit_gcrf": [3], "distance_m": d,
//         "target_unit_gcrf"?: [3] (only with target_offset_arcsec)}
// Apparent: light time and relativistic aberration by the observer's barycentric velocity;
// geometric: the Sun's centre at `time`; distance: observer to the Sun's centre at `time`.
// r_gcrf, v_gcrf: the observer's geocentric state (zero: the Earth's centre moving with the
// Earth). The ephemeris series is valid 1900-2100.

#include <string>

#include "visors/astro/apparent_sun.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/gps_time.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

Json run_sun(const Json& in) {
  reject_unknown_keys(in, {"time", "r_gcrf", "v_gcrf", "target_offset_arcsec"});
  const core::GpsTime t = take(core::GpsTime::parse(require_string(in, "time"), core::TimeScale::kUtc), "time");
  const int year = t.calendar(core::TimeScale::kUtc).year;
  if (year < 1900 || year >= 2100) throw ToolInputError("time", "must be within 1900-2099 (the solar ephemeris' span)");
  const core::StateVector observer{require_vector3(in, "r_gcrf"), require_vector3(in, "v_gcrf")};
  if (observer.r.norm() > 1e10) throw ToolInputError("r_gcrf", "must be a geocentric position within 1e10 m");
  if (!(observer.v.norm() < 0.01 * core::kSpeedOfLight)) throw ToolInputError("v_gcrf", "must be below 1 % of c");
  const astro::SunView view = astro::sun_view(t, observer);
  Json out{{"apparent_unit_gcrf", to_json(view.apparent_unit_gcrf)},
           {"geometric_unit_gcrf", to_json(view.geometric_unit_gcrf)},
           {"distance_m", view.distance_m}};
  if (in.contains("target_offset_arcsec")) {
    const auto offset = require_numbers(in, "target_offset_arcsec", "", 2);
    const Eigen::Vector2d offset_rad = Eigen::Vector2d(offset[0], offset[1]) * core::kArcsecToRad;
    if (offset_rad.norm() > 0.1) throw ToolInputError("target_offset_arcsec", "must be within 0.1 rad (20626\") of the Sun");
    out["target_unit_gcrf"] = to_json(astro::offset_on_sky(view.apparent_unit_gcrf, offset_rad));
  }
  return out;
}

const bool registered = register_tool(
    {"sun",
     "apparent Sun from a spacecraft {time (UTC), r_gcrf, v_gcrf, target_offset_arcsec?} -> apparent_unit_gcrf, "
     "geometric_unit_gcrf, distance_m, target_unit_gcrf?",
     run_sun});

}  // namespace
}  // namespace visors::tools
