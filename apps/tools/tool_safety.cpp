// `visors tool safety`: passive-safety evaluation of a relative orbit (safety/passive_safety.hpp).
//   {"chief":{a,e,i,raan,argp,M} (MEAN elements at t0), "roe":[6] (a*ROE, m), "cov"?:[[6x6]]
//    (covariance of a*ROE, m^2; default 0), "horizon": s, "plane":"rn"|"3d", "q": -,
//    "epsilon"?: m (default 5), "samples_per_orbit"?: (default 360)}
//     -> {"min_separation": m, "min_separation_margin": m, "t_min": s, "t_min_margin": s,
//         "sigma_at_t_min": m, "safe": bool}
// The horizon is converted to chief orbits with the Keplerian period 2 pi sqrt(a^3/mu).

#include <cmath>
#include <string>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/safety/passive_safety.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

// The library names the covariance "covariance"; the tool's key is "cov".
template <typename T>
T take_renamed(core::Outcome<T> result) {
  if (!result.ok() && result.error().field == "covariance") {
    throw ToolInputError("cov", result.error().message);
  }
  return take(std::move(result));
}

Json run_safety(const Json& in) {
  reject_unknown_keys(in, {"chief", "roe", "cov", "horizon", "plane", "q", "epsilon", "samples_per_orbit"});
  const astro::KeplerianElements chief =
      take(astro::validate_keplerian(require_keplerian(require_object(in, "chief"), "chief")), "chief");
  const core::EarthGravityConstants gravity;
  const astro::RelativeOrbitalElements roe = require_roe_m(in, "roe", chief.a);
  const safety::RoeCovariance cov = optional_roe_covariance_m2(in, "cov", chief.a);
  const double horizon = require_number(in, "horizon");
  if (!(horizon > 0.0)) throw ToolInputError("horizon", "must be > 0 s");
  safety::PassiveSafetySettings settings;
  settings.horizon_orbits = horizon / safety::orbital_period(chief, gravity.mu);
  const std::string plane = require_string(in, "plane");
  if (plane == "rn") {
    settings.plane = safety::SafetyPlane::kRadialNormal;
  } else if (plane == "3d") {
    settings.plane = safety::SafetyPlane::kThreeDimensional;
  } else {
    throw ToolInputError("plane", "must be \"rn\" or \"3d\"");
  }
  settings.q_sigma = require_number(in, "q");
  settings.epsilon_m = optional_number(in, "epsilon").value_or(settings.epsilon_m);
  if (const auto spo = optional_number(in, "samples_per_orbit")) {
    if (*spo != std::floor(*spo) || *spo < 8.0 || *spo > 100000.0) {
      throw ToolInputError("samples_per_orbit", "must be an integer in [8, 100000]");
    }
    settings.samples_per_orbit = static_cast<int>(*spo);
  }
  const auto checked = safety::validate(settings);
  if (!checked.ok()) {
    const std::string& f = checked.error().field;
    throw ToolInputError(f == "q_sigma" ? "q" : (f == "horizon_orbits" ? "horizon" : (f == "epsilon_m" ? "epsilon" : f)),
                         checked.error().message);
  }
  const safety::SafetyAssessment r =
      take_renamed(safety::evaluate_passive_safety(chief, roe, cov, settings, gravity));
  return Json{{"min_separation", r.min_separation_m},
              {"min_separation_margin", r.min_separation_margin_m},
              {"t_min", r.t_min_s},
              {"t_min_margin", r.t_min_margin_s},
              {"sigma_at_t_min", r.sigma_at_t_min_m},
              {"safe", r.safe}};
}

const bool registered = register_tool(
    {"safety", "passive safety {chief (mean), roe [m], cov? [m^2], horizon, plane: rn|3d, q, epsilon?} -> min separation, margin, safe",
     run_safety});

}  // namespace
}  // namespace visors::tools
