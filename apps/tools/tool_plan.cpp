// `visors tool plan`: fuel-optimal impulses between two relative orbits (mean ROE).
//   {"chief":{a,e,i,raan,argp,M} (MEAN, at t0), "roe_start":[6], "roe_target":[6] (a*dROE, m),
//    "t0": s, "tf": s, "algorithm": "closed-form" | "reachable-set" | "least-squares",
//    "times"?: [s] (least-squares: the 1-6 burn times), "nu"?: relative regularisation}
//     -> {"maneuvers":[{"t": s, "dv_rtn": [3] m/s}], "dv_total": m/s, "dv_lower_bound": m/s,
//         "roe_final_predicted": [6] m}
// Times (t0, tf, times, output t) are on one clock; the chief's elements are at t0. Models:
// secular-J2 STM and the eccentric control input matrix (control/impulse_effect.hpp).

#include <string>
#include <vector>

#include "visors/control/closed_form_planner.hpp"
#include "visors/control/least_squares_planner.hpp"
#include "visors/control/reachable_set_planner.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

Json run_plan(const Json& in) {
  reject_unknown_keys(in, {"chief", "roe_start", "roe_target", "t0", "tf", "algorithm", "times", "nu"});
  const astro::KeplerianElements chief =
      take(astro::validate_keplerian(require_keplerian(require_object(in, "chief"), "chief")), "chief");
  const astro::RelativeOrbitalElements roe0 = require_roe_m(in, "roe_start", chief.a);
  const astro::RelativeOrbitalElements target = require_roe_m(in, "roe_target", chief.a);
  const double t0 = optional_number(in, "t0").value_or(0.0);
  const double tf = require_number(in, "tf") - t0;
  if (!(tf > 0.0)) throw ToolInputError("tf", "must be after t0");
  const std::string algorithm = require_string(in, "algorithm");
  if (algorithm != "least-squares" && (in.contains("times") || in.contains("nu"))) {
    throw ToolInputError(in.contains("times") ? "times" : "nu", "applies to algorithm \"least-squares\" only");
  }

  control::ManeuverPlan plan;
  if (algorithm == "closed-form") {
    plan = take(control::plan_closed_form(chief, roe0, target, tf));
  } else if (algorithm == "reachable-set") {
    control::ReachableSetPlanner planner = take(control::ReachableSetPlanner::create());
    plan = take(planner.plan(chief, roe0, target, 0.0, tf));
  } else if (algorithm == "least-squares") {
    std::vector<double> times = require_numbers(in, "times");
    for (double& t : times) t -= t0;
    control::LeastSquaresSettings settings;
    settings.relative_regularisation = optional_number(in, "nu").value_or(settings.relative_regularisation);
    plan = take(control::plan_least_squares(chief, roe0, target, tf, times, settings)).plan;
  } else {
    throw ToolInputError("algorithm", "must be \"closed-form\", \"reachable-set\" or \"least-squares\"");
  }

  Json maneuvers = Json::array();
  for (const control::Impulse& i : plan.impulses) maneuvers.push_back({{"t", i.t + t0}, {"dv_rtn", to_json(i.dv_rtn)}});
  return Json{{"maneuvers", maneuvers},
              {"dv_total", plan.dv_total_mps},
              {"dv_lower_bound", plan.dv_lower_bound_mps},
              {"roe_final_predicted", roe_to_json_m(plan.roe_final_predicted, chief.a)}};
}

const bool registered = register_tool(
    {"plan", "impulsive maneuvers between relative orbits {chief, roe_start, roe_target, t0, tf, algorithm}",
     run_plan});

}  // namespace
}  // namespace visors::tools
