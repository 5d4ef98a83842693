#include "visors/config/force_model_toml.hpp"

#include "visors/config/toml_fields.hpp"

namespace visors::config {

using namespace dynamics;  // the configuration types this reader fills
namespace {

using core::Error;
using namespace config::toml_fields;

core::Result<GravityConfig> read_gravity(const toml::table& t, const std::string& s, GravityConfig g) {
  if (auto e = check_keys(t, s, {"model", "degree", "order", "allow_embedded_fallback"})) return *e;
  VISORS_TRY(model, string_at(t, s, "model", g.model));
  VISORS_TRY(degree, integer_at(t, s, "degree", g.degree));
  VISORS_TRY(order, integer_at(t, s, "order", std::min<std::int64_t>(degree, g.order)));
  VISORS_TRY(fallback, bool_at(t, s, "allow_embedded_fallback", g.allow_embedded_fallback));
  if (degree < 0 || degree > 360) return Error{field_name(s, "degree"), "must be in [0, 360]"};
  if (order < 0 || order > degree) return Error{field_name(s, "order"), "must be in [0, degree]"};
  return GravityConfig{model, static_cast<int>(degree), static_cast<int>(order), fallback};
}

core::Result<DragConfig> read_drag(const toml::table& t, const std::string& s, DragConfig d) {
  if (auto e = check_keys(t, s, {"enabled", "atmosphere", "cosine_exponent", "density_scale",
                                 "space_weather", "f107", "f107a", "ap", "nrlmsise00_coefficients", "ap_history"})) {
    return *e;
  }
  const char* kinds[] = {"harris-priester", "harris-priester-max", "nrlmsise00"};
  VISORS_TRY(enabled, bool_at(t, s, "enabled", d.enabled));
  VISORS_TRY(atmosphere, string_at(t, s, "atmosphere", kinds[static_cast<int>(d.atmosphere)]));
  VISORS_TRY(exponent, integer_at(t, s, "cosine_exponent", d.cosine_exponent));
  VISORS_TRY(scale, number_at(t, s, "density_scale", d.density_scale));
  VISORS_TRY(space_weather, string_at(t, s, "space_weather", d.space_weather));
  VISORS_TRY(f107, number_at(t, s, "f107", d.activity.f107));
  VISORS_TRY(f107a, number_at(t, s, "f107a", d.activity.f107a));
  VISORS_TRY(ap, number_at(t, s, "ap", d.activity.ap));
  VISORS_TRY(coefficients, string_at(t, s, "nrlmsise00_coefficients", d.nrlmsise00_coefficients));
  VISORS_TRY(ap_history, bool_at(t, s, "ap_history", d.ap_history));
  if (atmosphere == kinds[0]) {
    d.atmosphere = AtmosphereKind::kHarrisPriester;
  } else if (atmosphere == kinds[1]) {
    d.atmosphere = AtmosphereKind::kHarrisPriesterMaximum;
  } else if (atmosphere == kinds[2]) {
    d.atmosphere = AtmosphereKind::kNrlmsise00;
  } else {
    return Error{field_name(s, "atmosphere"), "must be \"harris-priester\", \"harris-priester-max\" or \"nrlmsise00\""};
  }
  if (exponent < 1 || exponent > 12) return Error{field_name(s, "cosine_exponent"), "must be in [1, 12]"};
  if (!(scale > 0.0)) return Error{field_name(s, "density_scale"), "must be > 0"};
  if (!(f107 > 0.0)) return Error{field_name(s, "f107"), "must be > 0 sfu"};
  if (!(f107a > 0.0)) return Error{field_name(s, "f107a"), "must be > 0 sfu"};
  if (ap < 0.0) return Error{field_name(s, "ap"), "must be >= 0"};
  d.enabled = enabled;
  d.cosine_exponent = static_cast<int>(exponent);
  d.density_scale = scale;
  d.space_weather = space_weather;
  d.nrlmsise00_coefficients = coefficients;
  d.ap_history = ap_history;
  d.activity.f107 = f107;
  d.activity.f107a = f107a;
  d.activity.ap = ap;
  return d;
}

core::Result<SrpConfig> read_srp(const toml::table& t, const std::string& s, SrpConfig srp) {
  if (auto e = check_keys(t, s, {"enabled", "pressure_1au", "shadow"})) return *e;
  VISORS_TRY(enabled, bool_at(t, s, "enabled", srp.enabled));
  VISORS_TRY(pressure, number_at(t, s, "pressure_1au", srp.pressure_1au));
  const char* names[] = {"none", "cylindrical", "conical"};
  VISORS_TRY(shadow, string_at(t, s, "shadow", names[static_cast<int>(srp.shadow)]));
  if (!(pressure > 0.0)) return Error{field_name(s, "pressure_1au"), "must be > 0 N/m^2"};
  for (int k = 0; k < 3; ++k) {
    if (shadow == names[k]) return SrpConfig{enabled, pressure, static_cast<ShadowModel>(k)};
  }
  return Error{field_name(s, "shadow"), "must be \"none\", \"cylindrical\" or \"conical\""};
}

core::Result<EarthFrameConfig> read_earth_frame(const toml::table& t, const std::string& s, EarthFrameConfig f) {
  if (auto e = check_keys(t, s, {"eop", "refresh_interval"})) return *e;
  VISORS_TRY(eop, string_at(t, s, "eop", f.eop));
  VISORS_TRY(refresh, number_at(t, s, "refresh_interval", f.refresh_interval));
  if (refresh < 0.0 || refresh > 86400.0) {
    return Error{field_name(s, "refresh_interval"), "must be in [0, 86400] s"};
  }
  return EarthFrameConfig{eop, refresh};
}

// Applies an optional sub-table reader.
template <typename T, typename Reader>
std::optional<Error> apply(const toml::table& parent, const std::string& section, std::string_view key,
                           T& value, Reader read) {
  const toml::node* node = parent.get(key);
  if (node == nullptr) return std::nullopt;
  const std::string name = field_name(section, key);
  if (!node->is_table()) return Error{name, "must be a table"};
  auto result = read(*node->as_table(), name, value);
  if (!result) return result.error();
  value = std::move(result).value();
  return std::nullopt;
}

}  // namespace

core::Result<ForceModelConfig> force_model_config_from_toml(const toml::table* forces, const std::string& s) {
  if (forces == nullptr) return ForceModelConfig::onboard();
  const toml::table& t = *forces;
  if (auto e = check_keys(t, s, {"preset", "sun", "moon", "empirical_rtn", "gravity", "drag", "srp",
                                 "earth_frame"})) {
    return *e;
  }
  VISORS_TRY(preset, string_at(t, s, "preset", "onboard"));
  ForceModelConfig config;
  if (preset == "truth") {
    config = ForceModelConfig::truth();
  } else if (preset == "onboard") {
    config = ForceModelConfig::onboard();
  } else {
    return Error{field_name(s, "preset"), "must be \"truth\" or \"onboard\""};
  }
  VISORS_TRY(sun, bool_at(t, s, "sun", config.sun));
  VISORS_TRY(moon, bool_at(t, s, "moon", config.moon));
  VISORS_TRY(empirical, vector3_at(t, s, "empirical_rtn", config.empirical_rtn));
  config.sun = sun;
  config.moon = moon;
  config.empirical_rtn = empirical;
  if (auto e = apply(t, s, "gravity", config.gravity, read_gravity)) return *e;
  if (auto e = apply(t, s, "drag", config.drag, read_drag)) return *e;
  if (auto e = apply(t, s, "srp", config.srp, read_srp)) return *e;
  if (auto e = apply(t, s, "earth_frame", config.earth_frame, read_earth_frame)) return *e;
  return config;
}

core::Result<SpacecraftProperties> spacecraft_from_toml(const toml::table* spacecraft, const std::string& s) {
  SpacecraftProperties p;
  if (spacecraft == nullptr) return p;
  const toml::table& t = *spacecraft;
  if (auto e = check_keys(t, s, {"mass", "drag_area", "cd", "srp_area", "cr"})) return *e;
  VISORS_TRY(mass, number_at(t, s, "mass", p.mass));
  VISORS_TRY(drag_area, number_at(t, s, "drag_area", p.drag_area));
  VISORS_TRY(cd, number_at(t, s, "cd", p.cd));
  VISORS_TRY(srp_area, number_at(t, s, "srp_area", p.srp_area));
  VISORS_TRY(cr, number_at(t, s, "cr", p.cr));
  const std::pair<const char*, double> positive[] = {
      {"mass", mass}, {"drag_area", drag_area}, {"cd", cd}, {"srp_area", srp_area}, {"cr", cr}};
  for (const auto& [key, value] : positive) {
    if (!(value > 0.0)) return Error{field_name(s, key), "must be > 0"};
  }
  return SpacecraftProperties{mass, drag_area, cd, srp_area, cr};
}

}  // namespace visors::config
