// `visors tool elements`: Cartesian state <-> Keplerian elements (two-body).
//   {"r":[3] m, "v":[3] m/s, "mu"?}            -> {"a","e","i","raan","argp","M","nu","u"}
//   {"a","e","i","raan","argp","M" (m, rad), "mu"?} -> {"r":[3],"v":[3]}
// u is the mean argument of latitude argp + M (docs/conventions.md), nu the true anomaly; angles
// in [0, 2 pi). Singular cases follow astro/keplerian_elements.hpp (e = 0: argp = 0; equatorial:
// raan = 0). mu defaults to 3.986004415e14 m^3/s^2.

#include <string>
#include <string_view>
#include <vector>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/angles.hpp"
#include "visors/core/constants.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

constexpr std::string_view kElementKeys[] = {"a", "e", "i", "raan", "argp", "M"};

Json run_elements(const Json& in) {
  const bool has_state = in.contains("r") || in.contains("v");
  bool has_elements = false;
  for (const auto key : kElementKeys) has_elements = has_elements || in.contains(std::string(key));
  if (has_state == has_elements) {
    throw ToolInputError("", "give exactly one of {r, v} or {a, e, i, raan, argp, M}");
  }
  const double mu = optional_number(in, "mu").value_or(core::EarthGravityConstants{}.mu);
  if (has_state) {
    reject_unknown_keys(in, {"r", "v", "mu"});
    const auto r = require_vector3(in, "r");
    const auto v = require_vector3(in, "v");
    const astro::KeplerianElements el = take(astro::cartesian_to_keplerian(r, v, mu));
    return Json{{"a", el.a},       {"e", el.e},   {"i", el.i},
                {"raan", el.raan}, {"argp", el.argp}, {"M", el.M},
                {"nu", core::wrap_two_pi(astro::true_anomaly(el))},
                {"u", core::wrap_two_pi(el.argp + el.M)}};
  }
  const astro::KeplerianElements el = require_keplerian(in, "", {"mu"});
  const visors::core::StateVector x = take(astro::keplerian_to_cartesian(el, mu));
  return Json{{"r", to_json(x.r)}, {"v", to_json(x.v)}};
}

const bool registered = register_tool(
    {"elements", "Cartesian {r,v} <-> Keplerian {a,e,i,raan,argp,M} (two-body, mu optional)",
     run_elements});

}  // namespace
}  // namespace visors::tools
