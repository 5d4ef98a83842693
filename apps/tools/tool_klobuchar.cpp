// `visors tool klobuchar`: the GPS broadcast ionospheric delay on L1 (gnss/klobuchar.hpp), the
// ground model.
//   {"alpha": [4], "beta": [4], "gps_time": "YYYY-MM-DDTHH:MM:SS", "lat": rad, "lon": rad,
//    "az": rad, "el": rad} -> {"delay_m": m}

#include <array>
#include <string>
#include <vector>

#include "visors/gnss/klobuchar.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

std::array<double, 4> require_four(const Json& in, const std::string& key) {
  const std::vector<double> values = require_numbers(in, key, "", 4);
  return {values[0], values[1], values[2], values[3]};
}

Json run_klobuchar(const Json& in) {
  reject_unknown_keys(in, {"alpha", "beta", "gps_time", "lat", "lon", "az", "el"});
  gnss::KlobucharCoefficients coefficients;
  coefficients.alpha = require_four(in, "alpha");
  coefficients.beta = require_four(in, "beta");
  const core::GpsTime t = take(core::GpsTime::parse(require_string(in, "gps_time"), core::TimeScale::kGps), "gps_time");
  const gnss::KlobucharGeometry geometry{require_number(in, "lat"), require_number(in, "lon"), require_number(in, "az"),
                                         require_number(in, "el")};
  return Json{{"delay_m", take(gnss::klobuchar_delay_m(coefficients, geometry, t))}};
}

const bool registered = register_tool(
    {"klobuchar", "GPS broadcast ionospheric delay on L1 {alpha[4], beta[4], gps_time, lat, lon, az, el (rad)} -> delay_m",
     run_klobuchar});

}  // namespace
}  // namespace visors::tools
