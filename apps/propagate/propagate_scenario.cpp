#include "apps/propagate/propagate_scenario.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/config/force_model_toml.hpp"
#include "visors/config/toml_fields.hpp"
#include "visors/core/angles.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/files/text_file.hpp"

namespace visors::propagate {
namespace {

using core::Error;
using namespace config::toml_fields;

core::Result<core::GpsTime> read_epoch(const toml::table& root) {
  const toml::table* epoch = root.get_as<toml::table>("epoch");
  if (epoch == nullptr) return Error{"epoch", "the [epoch] table is required"};
  if (auto e = check_keys(*epoch, "epoch", {"utc", "gps"})) return *e;
  const bool has_utc = epoch->contains("utc");
  if (has_utc == epoch->contains("gps")) return Error{"epoch", "give exactly one of utc or gps"};
  const std::string key = has_utc ? "utc" : "gps";
  VISORS_TRY(text, string_at(*epoch, "epoch", key, std::nullopt));
  auto t = core::GpsTime::parse(text, has_utc ? core::TimeScale::kUtc : core::TimeScale::kGps);
  if (!t) return Error{"epoch." + key, t.error().message};
  return t.value();
}

// Osculating Keplerian elements (degrees at the edge) or a Cartesian GCRF state.
core::Result<core::StateVector> read_initial_state(const toml::table& root, double mu) {
  const toml::table* s = root.get_as<toml::table>("initial_state");
  const std::string section = "initial_state";
  if (s == nullptr) return Error{section, "the [initial_state] table is required"};
  if (s->contains("r_gcrf") || s->contains("v_gcrf")) {
    if (auto e = check_keys(*s, section, {"r_gcrf", "v_gcrf"})) return *e;
    VISORS_TRY(r, vector3_at(*s, section, "r_gcrf", std::nullopt));
    VISORS_TRY(v, vector3_at(*s, section, "v_gcrf", std::nullopt));
    if (r.norm() < core::kWgs84SemiMajorAxis * (1.0 - core::kWgs84Flattening)) {
      return Error{section + ".r_gcrf", "position is inside the Earth"};
    }
    return core::StateVector{r, v};
  }
  if (auto e = check_keys(*s, section, {"a_m", "e", "i_deg", "raan_deg", "argp_deg", "M_deg"})) return *e;
  VISORS_TRY(a, number_at(*s, section, "a_m", std::nullopt));
  VISORS_TRY(ecc, number_at(*s, section, "e", std::nullopt));
  VISORS_TRY(i_deg, number_at(*s, section, "i_deg", std::nullopt));
  VISORS_TRY(raan_deg, number_at(*s, section, "raan_deg", std::nullopt));
  VISORS_TRY(argp_deg, number_at(*s, section, "argp_deg", 0.0));
  VISORS_TRY(m_deg, number_at(*s, section, "M_deg", 0.0));
  const astro::KeplerianElements k{a, ecc, i_deg * core::kDegToRad, raan_deg * core::kDegToRad,
                                   argp_deg * core::kDegToRad, m_deg * core::kDegToRad};
  auto valid = astro::validate_keplerian(k);
  if (!valid) return Error{section + "." + valid.error().field, valid.error().message};
  if (a * (1.0 - ecc) < core::kWgs84SemiMajorAxis + 100e3) {
    return Error{section + ".a_m", "perigee is below 100 km altitude"};
  }
  return astro::cartesian_from_keplerian(k, mu);
}

core::Result<dynamics::PropagatorSettings> read_integrator(const toml::table& p, const std::string& s) {
  dynamics::PropagatorSettings settings;
  VISORS_TRY(name, string_at(p, s, "integrator", "rk4"));
  if (name == "rk4") {
    settings.integrator = dynamics::IntegratorKind::kRk4Dynamic;
  } else if (name == "rk4-fixed") {
    settings.integrator = dynamics::IntegratorKind::kRk4Fixed;
  } else if (name == "dp87") {
    settings.integrator = dynamics::IntegratorKind::kDormandPrince87;
  } else {
    return Error{field_name(s, "integrator"), "must be \"rk4\", \"rk4-fixed\" or \"dp87\""};
  }
  VISORS_TRY(step, number_at(p, s, "step_s", settings.step_s));
  VISORS_TRY(min_step, number_at(p, s, "min_step_s", std::min(settings.min_step_s, step)));
  VISORS_TRY(rtol, number_at(p, s, "relative_tolerance", settings.reference.relative_tolerance));
  VISORS_TRY(atol, number_at(p, s, "absolute_tolerance", settings.reference.absolute_tolerance));
  if (!(step >= 1e-3) || step > 3600.0) return Error{field_name(s, "step_s"), "must be in [1 ms, 3600 s]"};
  if (!(min_step > 0.0) || min_step > step) return Error{field_name(s, "min_step_s"), "must be in (0, step_s]"};
  if (!(rtol > 0.0) || rtol >= 1.0) return Error{field_name(s, "relative_tolerance"), "must be in (0, 1)"};
  if (!(atol > 0.0)) return Error{field_name(s, "absolute_tolerance"), "must be > 0"};
  settings.step_s = step;
  settings.min_step_s = min_step;
  settings.reference.relative_tolerance = rtol;
  settings.reference.absolute_tolerance = atol;
  return settings;
}

core::Result<std::vector<dynamics::ImpulsiveManeuver>> read_maneuvers(const toml::table& root,
                                                                      core::GpsTime epoch, double duration) {
  std::vector<dynamics::ImpulsiveManeuver> maneuvers;
  const toml::node* node = root.get("maneuver");
  if (node == nullptr) return maneuvers;
  const toml::array* list = node->as_array();
  if (list == nullptr) return Error{"maneuver", "must be an array of tables ([[maneuver]])"};
  for (std::size_t k = 0; k < list->size(); ++k) {
    const std::string where = "maneuver[" + std::to_string(k) + "]";
    const toml::table* m = list->get(k)->as_table();
    if (m == nullptr) return Error{where, "must be a table"};
    if (auto e = check_keys(*m, where, {"t_s", "dv_rtn", "dv_gcrf"})) return *e;
    VISORS_TRY(t_s, number_at(*m, where, "t_s", std::nullopt));
    if (t_s < 0.0 || t_s > duration) return Error{where + ".t_s", "must be within [0, duration_s]"};
    const bool rtn = m->contains("dv_rtn");
    if (rtn == m->contains("dv_gcrf")) return Error{where, "give exactly one of dv_rtn or dv_gcrf"};
    VISORS_TRY(dv, vector3_at(*m, where, rtn ? "dv_rtn" : "dv_gcrf", std::nullopt));
    maneuvers.push_back({epoch + t_s, dv, rtn ? dynamics::ManeuverFrame::kRtn : dynamics::ManeuverFrame::kGcrf});
  }
  std::stable_sort(maneuvers.begin(), maneuvers.end(),
                   [](const auto& a, const auto& b) { return a.t < b.t; });
  return maneuvers;
}

}  // namespace

core::Result<PropagateScenario> parse_propagate_scenario(const std::string& toml_text) {
  VISORS_TRY(root, parse(toml_text));
  if (auto e = check_keys(root, "", {"name", "epoch", "initial_state", "propagation", "spacecraft",
                                     "forces", "maneuver"})) {
    return *e;
  }
  PropagateScenario s;
  VISORS_TRY(name, string_at(root, "", "name", s.name));
  if (name.empty() || !std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
      })) {
    return Error{"name", "must be non-empty letters, digits, '_' or '-' (it names the output files)"};
  }
  s.name = name;
  VISORS_TRY(epoch, read_epoch(root));
  s.epoch = epoch;
  VISORS_TRY(forces, config::force_model_config_from_toml(root.get_as<toml::table>("forces")));
  s.forces = forces;
  VISORS_TRY(spacecraft, config::spacecraft_from_toml(root.get_as<toml::table>("spacecraft")));
  s.spacecraft = spacecraft;
  // Initial elements use the GRACE-field GM, the GM of every shipped gravity model.
  VISORS_TRY(initial, read_initial_state(root, core::EarthGravityConstants{}.mu));
  s.initial_gcrf = initial;

  const toml::table* p = root.get_as<toml::table>("propagation");
  if (p == nullptr) return Error{"propagation", "the [propagation] table is required"};
  const std::string section = "propagation";
  if (auto e = check_keys(*p, section, {"duration_s", "output_step_s", "integrator", "step_s", "min_step_s",
                                        "relative_tolerance", "absolute_tolerance"})) {
    return *e;
  }
  VISORS_TRY(duration, number_at(*p, section, "duration_s", std::nullopt));
  VISORS_TRY(output_step, number_at(*p, section, "output_step_s", s.output_step));
  if (!(duration > 0.0) || duration > 366.0 * 86400.0) {
    return Error{"propagation.duration_s", "must be in (0, 366 days]"};
  }
  if (!(output_step >= 1e-3) || duration / output_step > 1e7) {
    return Error{"propagation.output_step_s", "must be >= 1 ms and give at most 1e7 records"};
  }
  s.duration = duration;
  s.output_step = output_step;
  VISORS_TRY(settings, read_integrator(*p, section));
  s.propagator = settings;
  VISORS_TRY(maneuvers, read_maneuvers(root, s.epoch, duration));
  s.maneuvers = maneuvers;
  return s;
}

core::Result<PropagateScenario> load_propagate_scenario(const std::filesystem::path& path) {
  const auto text = core::files::read_text_file(path);
  if (!text) return Error{"scenario", "cannot read " + path.string()};
  return parse_propagate_scenario(*text);
}

}  // namespace visors::propagate
