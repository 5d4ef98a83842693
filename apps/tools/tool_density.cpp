// `visors tool density`: modified Harris-Priester neutral density (dynamics/harris_priester.hpp).
//   {"model": "harris-priester" | "harris-priester-max", "r_gcrf": [m], "sun_gcrf": [m],
//    "f107": sfu, "time"?: "YYYY-MM-DDTHH:MM:SS" (UTC), "r_itrf"?: [m], "exponent"?: n}
//     -> {"density": kg/m^3, "height_m": m}
// harris-priester: the diurnal-bulge model with the embedded M&G table (mean activity), exponent
// n of cos(psi/2) (default 6). harris-priester-max: rho_max everywhere (the truth world's
// high-activity stand-in). f107 is used as the 81-day mean that selects the table (with the one
// embedded table it changes nothing; it is required so that callers state the activity).
// The geodetic height needs the Earth-fixed position: "r_itrf" if given (it must be the same
// point: |r_itrf| = |r_gcrf| to 1e-6 relative), else r_itrf = gcrf_to_itrf_matrix(time,
// EarthOrientation{}) r_gcrf, with "time" in UTC (default 2024-10-01T00:00:00) and zero EOP
// (polar motion and UT1-UTC ignored: <~ 10 m of position, negligible for the height).

#include <cmath>
#include <string>

#include "core/earth_frames.hpp"
#include "core/eop.hpp"
#include "core/geodetic.hpp"
#include "core/gps_time.hpp"
#include "dynamics/harris_priester.hpp"
#include "tools/tool.hpp"

namespace visors::tools {
namespace {

constexpr char kDefaultTime[] = "2024-10-01T00:00:00";

Eigen::Vector3d require_nonzero_vector3(const Json& in, const std::string& key) {
  const Eigen::Vector3d v = require_vector3(in, key);
  const double norm = v.norm();
  if (!std::isfinite(norm)) throw ToolInputError(key, "must have a finite norm");
  if (norm == 0.0) throw ToolInputError(key, "must be non-zero");
  return v;
}

Json run_density(const Json& in) {
  reject_unknown_keys(in, {"model", "r_gcrf", "sun_gcrf", "f107", "time", "r_itrf", "exponent"});
  const std::string model = require_string(in, "model");
  dynamics::HarrisPriesterSettings settings;
  if (model == "harris-priester") {
    settings.bulge = dynamics::HarrisPriesterBulge::kDiurnal;
  } else if (model == "harris-priester-max") {
    settings.bulge = dynamics::HarrisPriesterBulge::kApexMaximum;
  } else {
    throw ToolInputError("model", "must be \"harris-priester\" or \"harris-priester-max\"");
  }
  dynamics::AtmosphereQuery query;
  query.r_gcrf = require_nonzero_vector3(in, "r_gcrf");
  query.sun_gcrf = require_nonzero_vector3(in, "sun_gcrf");
  const double f107 = require_number(in, "f107");
  if (!(f107 > 0.0)) throw ToolInputError("f107", "must be > 0");
  query.activity.f107 = f107;
  query.activity.f107a = f107;
  settings.cosine_exponent = optional_number(in, "exponent").value_or(settings.cosine_exponent);

  const std::string time = in.contains("time") ? require_string(in, "time") : kDefaultTime;
  query.t = take(core::GpsTime::parse(time, core::TimeScale::kUtc), "time");
  if (in.contains("r_itrf")) {
    query.r_itrf = require_nonzero_vector3(in, "r_itrf");
    if (std::abs(query.r_itrf.norm() - query.r_gcrf.norm()) > 1e-6 * query.r_gcrf.norm()) {
      throw ToolInputError("r_itrf", "must be the point r_gcrf (|r_itrf| != |r_gcrf|)");
    }
  } else {
    query.r_itrf = core::gcrf_to_itrf_matrix(query.t, core::EarthOrientation{}) * query.r_gcrf;
  }

  auto created = dynamics::HarrisPriesterAtmosphere::create(settings);
  if (!created.ok() && created.error().field == "cosine_exponent") {
    throw ToolInputError("exponent", created.error().message);
  }
  const dynamics::HarrisPriesterAtmosphere atmosphere = take(std::move(created));
  return Json{{"density", atmosphere.density(query)},
              {"height_m", core::geodetic_from_itrf(query.r_itrf).height}};
}

const bool registered = register_tool(
    {"density",
     "Harris-Priester density {model: harris-priester|harris-priester-max, r_gcrf, sun_gcrf, f107, "
     "time?, r_itrf?, exponent?} -> density kg/m^3, height_m",
     run_density});

}  // namespace
}  // namespace visors::tools
