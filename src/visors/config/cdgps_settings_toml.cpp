#include "visors/config/cdgps_settings_toml.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <string_view>

#include "visors/config/toml_fields.hpp"

namespace visors::config {
namespace {

using namespace toml_fields;

struct NumberKey {
  std::string_view key;
  double nav::CdgpsSettings::*field;
};

struct FlagKey {
  std::string_view key;
  bool nav::CdgpsSettings::*field;
};

constexpr std::array<NumberKey, 32> kNumbers = {{
    {"max_step_s", &nav::CdgpsSettings::max_step_s},
    {"empirical_tau_s", &nav::CdgpsSettings::empirical_tau_s},
    {"empirical_sigma_mps2", &nav::CdgpsSettings::empirical_sigma_mps2},
    {"empirical_along_track_sigma_mps2", &nav::CdgpsSettings::empirical_along_track_sigma_mps2},
    {"empirical_common_sigma_mps2", &nav::CdgpsSettings::empirical_common_sigma_mps2},
    {"clock_random_walk_m", &nav::CdgpsSettings::clock_random_walk_m},
    {"impulse_magnitude_sigma", &nav::CdgpsSettings::impulse_magnitude_sigma},
    {"impulse_direction_sigma_deg", &nav::CdgpsSettings::impulse_direction_sigma_deg},
    {"position_sigma_m", &nav::CdgpsSettings::position_sigma_m},
    {"velocity_sigma_mps", &nav::CdgpsSettings::velocity_sigma_mps},
    {"clock_sigma_m", &nav::CdgpsSettings::clock_sigma_m},
    {"phase_center_sigma_m", &nav::CdgpsSettings::phase_center_sigma_m},
    {"min_float_s_before_fix", &nav::CdgpsSettings::min_float_s_before_fix},
    {"graphic_ambiguity_sigma_m", &nav::CdgpsSettings::graphic_ambiguity_sigma_m},
    {"graphic_bias_random_walk_m", &nav::CdgpsSettings::graphic_bias_random_walk_m},
    {"ephemeris_switch_sigma_m", &nav::CdgpsSettings::ephemeris_switch_sigma_m},
    {"sdcp_ambiguity_sigma_cycles", &nav::CdgpsSettings::sdcp_ambiguity_sigma_cycles},
    {"slot_timeout_s", &nav::CdgpsSettings::slot_timeout_s},
    {"graphic_sigma_m", &nav::CdgpsSettings::graphic_sigma_m},
    {"sdcp_sigma_m", &nav::CdgpsSettings::sdcp_sigma_m},
    {"sdcp_correlation_inflation", &nav::CdgpsSettings::sdcp_correlation_inflation},
    {"sdcp_multipath_sigma_m", &nav::CdgpsSettings::sdcp_multipath_sigma_m},
    {"sdcp_multipath_tau_s", &nav::CdgpsSettings::sdcp_multipath_tau_s},
    {"phase_center_turn_rate_deg_s", &nav::CdgpsSettings::phase_center_turn_rate_deg_s},
    {"phase_center_free_after_turn_s", &nav::CdgpsSettings::phase_center_free_after_turn_s},
    {"gate_sigmas", &nav::CdgpsSettings::gate_sigmas},
    {"sd_code_sigma_m", &nav::CdgpsSettings::sd_code_sigma_m},
    {"code_multipath_sigma_m", &nav::CdgpsSettings::code_multipath_sigma_m},
    {"code_multipath_tau_s", &nav::CdgpsSettings::code_multipath_tau_s},
    {"min_weighting_elevation_deg", &nav::CdgpsSettings::min_weighting_elevation_deg},
    {"min_fix_elevation_deg", &nav::CdgpsSettings::min_fix_elevation_deg},
    {"hold_variance_cycles2", &nav::CdgpsSettings::hold_variance_cycles2},
}};

constexpr std::array<FlagKey, 6> kFlags = {{
    {"sd_code", &nav::CdgpsSettings::sd_code},
    {"elevation_weighting", &nav::CdgpsSettings::elevation_weighting},
    {"ambiguity_resolution", &nav::CdgpsSettings::ambiguity_resolution},
    {"hold", &nav::CdgpsSettings::hold},
    {"phase_center_consider_between_turns", &nav::CdgpsSettings::phase_center_consider_between_turns},
    {"phase_center_boresight_estimated", &nav::CdgpsSettings::phase_center_boresight_estimated},
}};

std::optional<core::Error> check_nav_keys(const toml::table& table) {
  for (const auto& [key, value] : table) {
    const std::string_view name = key.str();
    const bool known = name == "acceptance" ||
                       std::any_of(kNumbers.begin(), kNumbers.end(), [&](const NumberKey& k) { return k.key == name; }) ||
                       std::any_of(kFlags.begin(), kFlags.end(), [&](const FlagKey& k) { return k.key == name; });
    if (!known) return core::Error{field_name("nav", name), "unknown key"};
  }
  return std::nullopt;
}

core::Result<bool> read_acceptance(const toml::table& table, nav::AcceptanceSettings& a) {
  const std::string section = "nav.acceptance";
  if (auto e = check_keys(table, section, {"min_success_rate", "min_ratio", "partial", "min_partial"})) return *e;
  VISORS_TRY(rate, number_at(table, section, "min_success_rate", a.min_success_rate));
  VISORS_TRY(ratio, number_at(table, section, "min_ratio", a.min_ratio));
  VISORS_TRY(partial, bool_at(table, section, "partial", a.partial));
  VISORS_TRY(min_partial, integer_at(table, section, "min_partial", a.min_partial));
  if (min_partial < 1 || min_partial > 64) return core::Error{section + ".min_partial", "must be in 1..64"};
  a.min_success_rate = rate;
  a.min_ratio = ratio;
  a.partial = partial;
  a.min_partial = static_cast<int>(min_partial);
  return true;
}

}  // namespace

core::Result<bool> read_cdgps_settings(const toml::table& root, nav::CdgpsSettings& settings) {
  const toml::node* node = root.get("nav");
  if (node == nullptr) return true;
  const toml::table* table = node->as_table();
  if (table == nullptr) return core::Error{"nav", "must be a table"};
  if (auto e = check_nav_keys(*table)) return *e;
  nav::CdgpsSettings out = settings;
  for (const NumberKey& k : kNumbers) {
    VISORS_TRY(value, number_at(*table, "nav", k.key, out.*k.field));
    out.*k.field = value;
  }
  for (const FlagKey& k : kFlags) {
    VISORS_TRY(value, bool_at(*table, "nav", k.key, out.*k.field));
    out.*k.field = value;
  }
  if (const toml::node* acceptance = table->get("acceptance")) {
    if (acceptance->as_table() == nullptr) return core::Error{"nav.acceptance", "must be a table"};
    if (auto ok = read_acceptance(*acceptance->as_table(), out.acceptance); !ok) return ok.error();
  }
  if (const core::Status e = nav::check(out); !e) return e.within("nav").error();
  settings = out;
  return true;
}

}  // namespace visors::config
