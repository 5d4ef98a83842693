// `visors tool stm`: state transition matrix of mean quasi-nonsingular ROE.
//   {"chief":{a,e,i,raan,argp,M}, "dt": s, "model": "j2"|"kepler", "j2"?, "re"?, "mu"?}
//     -> {"phi": 6x6 rows}
// chief = MEAN Keplerian elements at the start of the interval. Defaults J2 = 1.08262668e-3,
// re = 6378136.3 m, mu = 3.986004415e14 m^3/s^2. j2: Koenig, Guffanti & D'Amico 2017 eq. (A6).

#include <string>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/roe_stm.hpp"
#include "visors/core/constants.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

astro::KeplerianElements read_elements(const Json& in, const std::string& key) {
  return require_keplerian(require_object(in, key), key);
}

Json run_stm(const Json& in) {
  reject_unknown_keys(in, {"chief", "dt", "model", "j2", "re", "mu"});
  const astro::KeplerianElements chief = take(astro::validate_keplerian(read_elements(in, "chief")), "chief");
  const double dt = require_number(in, "dt");
  const std::string model = require_string(in, "model");
  core::EarthGravityConstants gravity;
  gravity.j2 = optional_number(in, "j2").value_or(gravity.j2);
  gravity.re = optional_number(in, "re").value_or(gravity.re);
  gravity.mu = optional_number(in, "mu").value_or(gravity.mu);
  if (gravity.j2 < 0.0) throw ToolInputError("j2", "must be >= 0");
  if (gravity.re <= 0.0) throw ToolInputError("re", "must be > 0");
  if (gravity.mu <= 0.0) throw ToolInputError("mu", "must be > 0");
  astro::RoeStm phi;
  if (model == "j2") {
    phi = astro::j2_roe_stm(chief, dt, gravity);
  } else if (model == "kepler") {
    phi = astro::keplerian_roe_stm(chief, dt, gravity.mu);
  } else {
    throw ToolInputError("model", "must be \"j2\" or \"kepler\"");
  }
  Json rows = Json::array();
  for (int r = 0; r < 6; ++r) {
    Json row = Json::array();
    for (int c = 0; c < 6; ++c) row.push_back(phi(r, c));
    rows.push_back(row);
  }
  return Json{{"phi", rows}};
}

const bool registered = register_tool(
    {"stm", "ROE state transition matrix {chief (mean), dt, model: j2|kepler} -> phi 6x6", run_stm});

}  // namespace
}  // namespace visors::tools
