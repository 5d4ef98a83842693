// `visors tool roe`: quasi-nonsingular relative orbital elements (docs/conventions.md) of a
// deputy w.r.t. a chief, both given as Keplerian elements (m, rad).
//   {"chief":{a,e,i,raan,argp,M}, "deputy":{...}} -> {"roe":[da,dlambda,dex,dey,dix,diy]}
// The ROE are dimensionless (multiply by chief a for metres).

#include <string>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

astro::KeplerianElements read_elements(const Json& in, const std::string& key) {
  return require_keplerian(require_object(in, key), key);
}

Json run_roe(const Json& in) {
  reject_unknown_keys(in, {"chief", "deputy"});
  const astro::KeplerianElements chief = read_elements(in, "chief");
  const astro::KeplerianElements deputy = read_elements(in, "deputy");
  const astro::RelativeOrbitalElements roe = take(astro::roe_from_keplerian(chief, deputy));
  Json out = Json::array();
  for (int k = 0; k < 6; ++k) out.push_back(roe[k]);
  return Json{{"roe", out}};
}

const bool registered = register_tool(
    {"roe", "quasi-nonsingular ROE [da,dlambda,dex,dey,dix,diy] of {deputy} w.r.t. {chief}", run_roe});

}  // namespace
}  // namespace visors::tools
