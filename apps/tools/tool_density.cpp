// `visors tool density`: neutral density of the modified Harris-Priester model
// (dynamics/harris_priester.hpp) or NRLMSISE-00 (dynamics/nrlmsise00.hpp).
//   {"model": "harris-priester" | "harris-priester-max", "r_gcrf": [m], "sun_gcrf": [m],
//    "f107": sfu, "time"?: "YYYY-MM-DDTHH:MM:SS" (UTC), "r_itrf"?: [m], "exponent"?: n}
//     -> {"density": kg/m^3, "height_m": m}
//   {"model": "nrlmsise00", "time": UTC, "lat_deg", "lon_deg", "alt_m" (geodetic), "f107"
//    (previous day's), "f107a" (81-day centred mean), "ap" (daily), "ap_array"?: [7]}
//     -> {"density": kg/m^3, "density_without_anomalous_o": kg/m^3, "temperature_k",
//         "exospheric_temperature_k"}
// harris-priester: the diurnal-bulge model with the embedded M&G table (mean activity), exponent
// n of cos(psi/2) (default 6). harris-priester-max: rho_max everywhere (the truth world's
// former high-activity stand-in, now NRLMSISE-00's fallback). f107 is used as the 81-day mean that selects the table (with the one
// embedded table it changes nothing; it is required so that callers state the activity).
// The geodetic height needs the Earth-fixed position: "r_itrf" if given (it must be the same
// point: |r_itrf| = |r_gcrf| to 1e-6 relative), else r_itrf = gcrf_to_itrf_matrix(time,
// EarthOrientation{}) r_gcrf, with "time" in UTC (default 2024-10-01T00:00:00) and zero EOP
// (polar motion and UT1-UTC ignored: <~ 10 m of position, negligible for the height).
// nrlmsise00: the model's conventions (dynamics/nrlmsise00.hpp): day of year and UT seconds of
// "time", local solar time UT/3600 + lon/15; "ap_array" (the model's 7-element ap history)
// selects its ap-history mode, else the daily-Ap mode. "density" is gtd7d's total mass density
// including anomalous oxygen (what the truth's drag uses), "density_without_anomalous_o" gtd7's
// (the published test values'). Heights 0..1000 km. The coefficient tables are read from
// atmosphere/nrlmsise00_coefficients.txt on the data search path.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "visors/core/earth_frames.hpp"
#include "visors/core/eop.hpp"
#include "visors/core/geodetic.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/dynamics/files/nrlmsise00_file.hpp"
#include "visors/dynamics/harris_priester.hpp"
#include "visors/dynamics/nrlmsise00.hpp"
#include "apps/tools/tool.hpp"

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

// The input field of each NRLMSISE-00 input (errors of Nrlmsise00Atmosphere::input_problem).
std::string nrlmsise00_field(const std::string& field) {
  if (field == "altitude_km") return "alt_m";
  if (field == "latitude_deg") return "lat_deg";
  if (field == "longitude_deg") return "lon_deg";
  if (field == "day_of_year" || field == "ut_seconds" || field == "local_solar_time_h") return "time";
  if (field.rfind("activity.ap_history", 0) == 0) return "ap_array" + field.substr(19);
  if (field.rfind("activity.", 0) == 0) return field.substr(9);
  return field;
}

Json run_nrlmsise00(const Json& in) {
  reject_unknown_keys(in, {"model", "time", "lat_deg", "lon_deg", "alt_m", "f107", "f107a", "ap", "ap_array"});
  const core::GpsTime t = take(core::GpsTime::parse(require_string(in, "time"), core::TimeScale::kUtc), "time");
  const double lat = require_number(in, "lat_deg");
  const double lon = require_number(in, "lon_deg");
  const double alt = require_number(in, "alt_m");
  if (std::abs(lat) > 90.0) throw ToolInputError("lat_deg", "must be in [-90, 90]");
  if (std::abs(lon) > 180.0) throw ToolInputError("lon_deg", "must be in [-180, 180]");
  // The model's inputs at (lat, lon, alt) and t, as the force model forms them from a position.
  dynamics::AtmosphereQuery query;
  query.t = t;
  query.r_itrf = core::itrf_from_geodetic({lat * core::kDegToRad, lon * core::kDegToRad, alt});
  dynamics::Nrlmsise00Input input = dynamics::Nrlmsise00Atmosphere::input_at(query);
  input.latitude_deg = lat;  // exactly as given (not through the Cartesian round trip)
  input.longitude_deg = lon;
  input.altitude_km = alt / 1e3;
  input.local_solar_time_h = input.ut_seconds / 3600.0 + lon / 15.0;
  input.activity.f107 = require_number(in, "f107");
  input.activity.f107a = require_number(in, "f107a");
  input.activity.ap = require_number(in, "ap");
  if (in.contains("ap_array")) {
    const std::vector<double> ap = require_numbers(in, "ap_array", "", 7);
    std::array<double, 7> history{};
    std::copy(ap.begin(), ap.end(), history.begin());
    input.activity.ap_history = history;
  }
  if (auto problem = dynamics::Nrlmsise00Atmosphere::input_problem(input)) {
    throw ToolInputError(nrlmsise00_field(problem->field), problem->message);
  }
  const std::string file = "atmosphere/nrlmsise00_coefficients.txt";
  const auto path = core::files::find_data_file(file);
  if (!path) {
    throw ToolInputError("model", "nrlmsise00: '" + file +
                                      "' not found (searched VISORS_DATA_PATH and the repository's data/ folder)");
  }
  const auto coefficients = take(dynamics::files::read_nrlmsise00_coefficients(*path), "model");
  const auto atmosphere = take(dynamics::Nrlmsise00Atmosphere::create(coefficients), "model");
  const dynamics::Nrlmsise00Output out = take(atmosphere.evaluate(input));
  return Json{{"density", out.mass_density_with_anomalous_o},
              {"density_without_anomalous_o", out.mass_density},
              {"temperature_k", out.temperature},
              {"exospheric_temperature_k", out.exospheric_temperature}};
}

Json run_harris_priester(const Json& in) {
  reject_unknown_keys(in, {"model", "r_gcrf", "sun_gcrf", "f107", "time", "r_itrf", "exponent"});
  const std::string model = require_string(in, "model");
  dynamics::HarrisPriesterSettings settings;
  if (model == "harris-priester") {
    settings.bulge = dynamics::HarrisPriesterBulge::kDiurnal;
  } else {
    settings.bulge = dynamics::HarrisPriesterBulge::kApexMaximum;
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

Json run_density(const Json& in) {
  const std::string model = require_string(in, "model");
  if (model == "nrlmsise00") return run_nrlmsise00(in);
  if (model == "harris-priester" || model == "harris-priester-max") return run_harris_priester(in);
  throw ToolInputError("model", "must be \"harris-priester\", \"harris-priester-max\" or \"nrlmsise00\"");
}

const bool registered = register_tool(
    {"density",
     "neutral density {model: harris-priester|harris-priester-max, r_gcrf, sun_gcrf, f107, time?, "
     "r_itrf?, exponent?} -> density kg/m^3, height_m; {model: nrlmsise00, time, lat_deg, lon_deg, alt_m, "
     "f107, f107a, ap, ap_array?} -> density, density_without_anomalous_o, temperature_k, "
     "exospheric_temperature_k",
     run_density});

}  // namespace
}  // namespace visors::tools
