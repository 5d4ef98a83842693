// `visors tool buffer`: a planned impulse -> actuator-feasible pieces with the same net effect.
//   {"chief":{a,e,i,raan,argp,M} (mean, at t = 0), "maneuver":{"t": s, "dv_rtn": [3] m/s},
//    "mass": kg, "max_impulse"?: N s, "min_impulse"?: N s, "quantum"?: N s, "spacing"?: s}
//     -> {"pieces":[{"t","dv_rtn"}], "dv_total": m/s, "residual_roe_m": [6] (a*dROE left by
//         the quantisation)}
// Defaults: the mission's propulsion (2.2e-2, 1e-3, 6e-5 N s, 46.5 s). See control/maneuver_buffer.hpp.

#include <string>

#include "visors/control/maneuver_buffer.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

Json run_buffer(const Json& in) {
  reject_unknown_keys(in, {"chief", "maneuver", "mass", "max_impulse", "min_impulse", "quantum", "spacing"});
  const astro::KeplerianElements chief = take(astro::validate_keplerian(require_keplerian(require_object(in, "chief"), "chief")), "chief");
  const Json& maneuver = require_object(in, "maneuver");
  reject_unknown_keys(maneuver, {"t", "dv_rtn"}, "maneuver");
  const control::Impulse impulse{require_number(maneuver, "t", "maneuver"), require_vector3(maneuver, "dv_rtn", "maneuver")};
  const double mass = require_number(in, "mass");
  control::BufferSettings settings;
  settings.limits.max_impulse_ns = optional_number(in, "max_impulse").value_or(settings.limits.max_impulse_ns);
  settings.limits.min_impulse_ns = optional_number(in, "min_impulse").value_or(settings.limits.min_impulse_ns);
  settings.limits.quantum_ns = optional_number(in, "quantum").value_or(settings.limits.quantum_ns);
  settings.limits.spacing_s = optional_number(in, "spacing").value_or(settings.limits.spacing_s);
  const control::BufferedManeuver out = take(control::buffer_impulse(chief, impulse, mass, settings));
  Json pieces = Json::array();
  for (const control::Impulse& p : out.pieces) pieces.push_back({{"t", p.t}, {"dv_rtn", to_json(p.dv_rtn)}});
  Json residual = Json::array();
  for (int k = 0; k < 6; ++k) residual.push_back(out.residual_roe_m[k]);
  return Json{{"pieces", pieces}, {"dv_total", out.dv_total_mps}, {"residual_roe_m", residual}};
}

const bool registered = register_tool(
    {"buffer", "split an impulse into actuator-feasible pieces {chief, maneuver{t, dv_rtn}, mass} -> pieces",
     run_buffer});

}  // namespace
}  // namespace visors::tools
