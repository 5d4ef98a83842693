// `visors tool escape`: single-impulse escape maneuver (safety/escape_maneuver.hpp).
//   {"chief":{a,e,i,raan,argp,M} (MEAN elements at t0), "roe":[6] (a*ROE at t0, m),
//    "cov":[[6x6]] (covariance of a*ROE, m^2), "t_earliest": s, "epsilon": m, "da_target": m,
//    "q"?: - (default 3)}
//     -> {"maneuver":{"t": s, "dv_rtn":[3] m/s}, "roe_after":[6] (a*ROE just after the burn, m),
//         "drift_per_orbit": m, "min_separation_after": m, "min_separation_margin_after": m}

#include <cmath>
#include <string>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/safety/escape_maneuver.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

Json run_escape(const Json& in) {
  reject_unknown_keys(in, {"chief", "roe", "cov", "t_earliest", "epsilon", "da_target", "q"});
  const astro::KeplerianElements chief =
      take(astro::validate_keplerian(require_keplerian(require_object(in, "chief"), "chief")), "chief");
  const core::EarthGravityConstants gravity;
  const astro::RelativeOrbitalElements roe = require_roe_m(in, "roe", chief.a);
  const safety::RoeCovariance cov = require_matrix(in, "cov", 6, 6) / (chief.a * chief.a);  // [m^2] -> [-]
  const double t_earliest = require_number(in, "t_earliest");
  safety::EscapeSettings settings;
  settings.epsilon_m = require_number(in, "epsilon");
  settings.da_target_m = require_number(in, "da_target");
  settings.q_sigma = optional_number(in, "q").value_or(settings.q_sigma);
  auto result = safety::plan_escape(chief, roe, cov, t_earliest, settings, gravity);
  if (!result.ok()) {
    // The JSON keys of this tool are the settings' names without their unit suffix.
    const std::string& f = result.error().field;
    const std::string key = f == "covariance" ? "cov"
                            : f == "q_sigma"  ? "q"
                            : f == "epsilon_m" ? "epsilon"
                            : f == "da_target_m" ? "da_target"
                                                 : f;
    throw ToolInputError(key, result.error().message);
  }
  const safety::EscapeManeuver& e = result.value();
  return Json{{"maneuver", {{"t", e.impulse.t}, {"dv_rtn", to_json(e.impulse.dv_rtn)}}},
              {"roe_after", roe_to_json_m(e.roe_after, chief.a)},
              {"drift_per_orbit", e.drift_per_orbit_m},
              {"min_separation_after", e.safety_after.min_separation_m},
              {"min_separation_margin_after", e.safety_after.min_separation_margin_m}};
}

const bool registered = register_tool(
    {"escape", "single-impulse escape {chief (mean), roe [m], cov [m^2], t_earliest, epsilon, da_target} -> maneuver, roe_after",
     run_escape});

}  // namespace
}  // namespace visors::tools
