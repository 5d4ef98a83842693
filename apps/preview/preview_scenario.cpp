#include "apps/preview/preview_scenario.hpp"

#include <cctype>
#include <cmath>

#include "visors/config/toml_fields.hpp"
#include "visors/core/angles.hpp"
#include "visors/core/files/text_file.hpp"

namespace visors::preview {
namespace {

using core::Error;

using config::toml_fields::check_keys;
using config::toml_fields::number_at;

const toml::table* section_of(const toml::table& root, const std::string& name) {
  return root.get_as<toml::table>(name);
}

core::Result<astro::KeplerianElements> parse_chief(const toml::table& chief,
                                                   const core::EarthGravityConstants& earth) {
  if (auto e = check_keys(chief, "chief", {"altitude_km", "e", "i_deg", "raan_deg", "argp_deg", "u_deg"})) {
    return *e;
  }
  VISORS_TRY(altitude_km, number_at(chief, "chief", "altitude_km", std::nullopt));
  VISORS_TRY(e, number_at(chief, "chief", "e", std::nullopt));
  VISORS_TRY(i_deg, number_at(chief, "chief", "i_deg", std::nullopt));
  VISORS_TRY(raan_deg, number_at(chief, "chief", "raan_deg", std::nullopt));
  VISORS_TRY(argp_deg, number_at(chief, "chief", "argp_deg", 0.0));
  VISORS_TRY(u_deg, number_at(chief, "chief", "u_deg", 0.0));
  if (altitude_km < 100.0) return Error{"chief.altitude_km", "must be at least 100 km"};
  if (e < 0.0 || e >= 0.9) return Error{"chief.e", "must be in [0, 0.9)"};
  if (i_deg <= 0.5 || i_deg >= 179.5) {
    return Error{"chief.i_deg", "must be in (0.5, 179.5): the quasi-nonsingular ROE are singular "
                                "for equatorial chiefs"};
  }
  astro::KeplerianElements k;
  k.a = earth.re + altitude_km * 1e3;
  if (k.a * (1.0 - e) < earth.re + 100e3) {
    return Error{"chief.e", "perigee is below 100 km altitude"};
  }
  k.e = e;
  k.i = i_deg * core::kDegToRad;
  k.raan = core::wrap_two_pi(raan_deg * core::kDegToRad);
  k.argp = core::wrap_two_pi(argp_deg * core::kDegToRad);
  k.M = core::wrap_two_pi((u_deg - argp_deg) * core::kDegToRad);
  return k;
}

core::Result<std::vector<FormationSpec>> parse_formations(const toml::table& root) {
  const toml::array* list = root.get_as<toml::array>("formation");
  if (list == nullptr || list->empty()) {
    return Error{"formation", "at least one [[formation]] table is required"};
  }
  std::vector<FormationSpec> formations;
  for (std::size_t k = 0; k < list->size(); ++k) {
    const std::string where = "formation[" + std::to_string(k) + "]";
    const toml::table* f = list->get(k)->as_table();
    if (f == nullptr) return Error{where, "must be a table"};
    if (auto e = check_keys(*f, where, {"name", "roe_m"})) return *e;
    FormationSpec spec;
    const auto name = f->get_as<std::string>("name");
    if (name == nullptr || name->get().empty()) return Error{where + ".name", "must be a non-empty string"};
    spec.name = name->get();
    for (char c : spec.name) {
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) {
        return Error{where + ".name", "may contain only letters, digits, '_' and '-' (it names a file)"};
      }
    }
    for (const auto& other : formations) {
      if (other.name == spec.name) return Error{where + ".name", "duplicates '" + spec.name + "'"};
    }
    const toml::array* roe = f->get_as<toml::array>("roe_m");
    if (roe == nullptr || roe->size() != 6) return Error{where + ".roe_m", "must be an array of 6 numbers"};
    for (std::size_t j = 0; j < 6; ++j) {
      const auto v = roe->get(j)->value<double>();
      if (!v || !std::isfinite(*v)) {
        return Error{where + ".roe_m[" + std::to_string(j) + "]", "must be a finite number"};
      }
      spec.roe_m[j] = *v;
    }
    formations.push_back(spec);
  }
  return formations;
}

}  // namespace

core::Result<PreviewScenario> parse_preview_scenario(const std::string& toml_text) {
  VISORS_TRY(root, config::toml_fields::parse(toml_text));
  if (auto e = check_keys(root, "", {"epoch", "chief", "earth", "run", "formation"})) return *e;

  PreviewScenario s;
  if (const auto* earth = section_of(root, "earth")) {
    if (auto e = check_keys(*earth, "earth", {"mu", "re", "j2"})) return *e;
    VISORS_TRY(mu, number_at(*earth, "earth", "mu", s.earth.mu));
    VISORS_TRY(re, number_at(*earth, "earth", "re", s.earth.re));
    VISORS_TRY(j2, number_at(*earth, "earth", "j2", s.earth.j2));
    if (mu <= 0.0) return Error{"earth.mu", "must be positive"};
    if (re <= 0.0) return Error{"earth.re", "must be positive"};
    if (std::abs(j2) > 0.01) return Error{"earth.j2", "must be a small dimensionless coefficient (|J2| <= 0.01)"};
    s.earth = {mu, re, j2};
  }

  const auto* epoch = section_of(root, "epoch");
  if (epoch == nullptr) return Error{"epoch", "the [epoch] table is required"};
  if (auto e = check_keys(*epoch, "epoch", {"gps"})) return *e;
  const auto gps = epoch->get_as<std::string>("gps");
  if (gps == nullptr) return Error{"epoch.gps", "must be a string \"YYYY-MM-DDTHH:MM:SS\" (GPS scale)"};
  auto t0 = core::GpsTime::parse(gps->get(), core::TimeScale::kGps);
  if (!t0.ok()) return Error{"epoch.gps", t0.error().message};
  s.epoch = t0.value();

  const auto* chief = section_of(root, "chief");
  if (chief == nullptr) return Error{"chief", "the [chief] table is required"};
  VISORS_TRY(chief_mean, parse_chief(*chief, s.earth));
  s.chief_mean = chief_mean;

  if (const auto* run = section_of(root, "run")) {
    if (auto e = check_keys(*run, "run", {"orbits", "step_s", "eop_file"})) return *e;
    VISORS_TRY(orbits, number_at(*run, "run", "orbits", s.orbits));
    VISORS_TRY(step_s, number_at(*run, "run", "step_s", s.step_s));
    if (orbits <= 0.0 || orbits > 1000.0) return Error{"run.orbits", "must be in (0, 1000]"};
    if (step_s < 0.1 || step_s > 3600.0) return Error{"run.step_s", "must be in [0.1, 3600] s"};
    s.orbits = orbits;
    s.step_s = step_s;
    if (const toml::node* eop = run->get("eop_file")) {
      const auto path = eop->value<std::string>();
      if (!path) return Error{"run.eop_file", "must be a string (a path found via VISORS_DATA_PATH)"};
      s.eop_file = *path;
    }
  }

  VISORS_TRY(formations, parse_formations(root));
  s.formations = formations;
  return s;
}

core::Result<PreviewScenario> load_preview_scenario(const std::filesystem::path& path) {
  const auto text = core::files::read_text_file(path);
  if (!text) return Error{path.string(), "cannot be opened"};
  return parse_preview_scenario(*text);
}

}  // namespace visors::preview
