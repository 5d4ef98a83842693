#include "visors/gnc/files/flight_config_json.hpp"

#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "visors/dynamics/files/force_model_files.hpp"

// JSON forms of the flight configuration structs: each field once, by its name in the struct, both
// ways (the macros define to_json and from_json; the hand-written pairs are the structs with an
// optional, a fixed-capacity array or a field of their own form).
namespace nlohmann {
// A column vector as a list of its N numbers; a matrix as a list of its rows.
template <int R, int C>
struct adl_serializer<Eigen::Matrix<double, R, C>> {
  static void to_json(json& j, const Eigen::Matrix<double, R, C>& m) {
    j = json::array();
    for (int r = 0; r < R; ++r) {
      if constexpr (C == 1) {
        j.push_back(m(r, 0));
      } else {
        json row = json::array();
        for (int c = 0; c < C; ++c) row.push_back(m(r, c));
        j.push_back(row);
      }
    }
  }
  static void from_json(const json& j, Eigen::Matrix<double, R, C>& m) {
    if (!j.is_array() || j.size() != static_cast<std::size_t>(R)) {
      throw std::invalid_argument("a list of " + std::to_string(R) + (C == 1 ? " numbers" : " rows") + " expected");
    }
    for (int r = 0; r < R; ++r) {
      const json& row = j.at(static_cast<std::size_t>(r));
      if constexpr (C == 1) {
        m(r, 0) = row.get<double>();
      } else {
        if (!row.is_array() || row.size() != static_cast<std::size_t>(C)) {
          throw std::invalid_argument("rows of " + std::to_string(C) + " numbers expected");
        }
        for (int c = 0; c < C; ++c) m(r, c) = row.at(static_cast<std::size_t>(c)).get<double>();
      }
    }
  }
};
}  // namespace nlohmann

namespace visors::core {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EarthGravityConstants, mu, re, j2)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EarthOrientation, xp, yp, dut1, lod, dx, dy)
}  // namespace visors::core

namespace visors::optim {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ConicSettings, max_iterations, feasibility_tolerance, absolute_gap_tolerance,
                                   relative_gap_tolerance, step_fraction, static_regularisation, dynamic_epsilon,
                                   dynamic_delta, refinement_steps, refinement_tolerance, equilibration_passes,
                                   psd_tolerance)
}  // namespace visors::optim

namespace visors::control {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ReachableSetSettings, grid_points, working_set_size, anchor_points, max_impulses,
                                   max_candidates, max_exchange_iterations, dual_tolerance, contact_tolerance,
                                   min_horizon_orbits, dual_box, terminal_tolerance_m, gravity, solver)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StochasticMpcSettings, planner, mahalanobis_threshold, execution_sigma_fraction,
                                   execution_sigma_floor_mps, terminal_process_noise, freeze_time_s, burn_latency_s)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LeastSquaresSettings, relative_regularisation, min_reciprocal_condition)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ActuatorLimits, max_impulse_ns, min_impulse_ns, quantum_ns, spacing_s)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(BufferSettings, limits, max_pieces, cap_margin, gravity)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(TransferSettings, max_phase_step, max_size_ratio)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StandbyOrbit, separation_m, phase_rad)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ScienceGeometry, focal_distance_m, north, los_rate_mps, offset_rtn_m, target_offset_rad)
}  // namespace visors::control

namespace visors::safety {
NLOHMANN_JSON_SERIALIZE_ENUM(SafetyPlane, {{SafetyPlane::kRadialNormal, "rn"}, {SafetyPlane::kThreeDimensional, "3d"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PassiveSafetySettings, epsilon_m, horizon_orbits, q_sigma, plane, check_period_s,
                                   samples_per_orbit)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EscapeSettings, epsilon_m, da_target_m, q_sigma, horizon_orbits, plane,
                                   samples_per_orbit, psi_samples, time_step_s, search_window_orbits, dv_sigma_mps)
}  // namespace visors::safety

namespace visors::nav {
NLOHMANN_JSON_SERIALIZE_ENUM(Craft, {{Craft::kDsc, "dsc"}, {Craft::kOsc, "osc"}})
NLOHMANN_JSON_SERIALIZE_ENUM(AcceptanceRule, {{AcceptanceRule::kSuccessRate, "success_rate"},
                                              {AcceptanceRule::kRatio, "ratio"},
                                              {AcceptanceRule::kSuccessRateAndRatio, "success_rate_and_ratio"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(AcceptanceSettings, rule, min_success_rate, min_ratio, partial, min_partial)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CdgpsSettings, local, max_step_s, empirical_tau_s, empirical_common_sigma_mps2,
                                   empirical_sigma_mps2, empirical_along_track_sigma_mps2, clock_random_walk_m, graphic_bias_random_walk_m,
                                   ephemeris_switch_sigma_m, impulse_magnitude_sigma, impulse_direction_sigma_deg,
                                   position_sigma_m, velocity_sigma_mps, clock_sigma_m, phase_center_sigma_m,
                                   phase_center_consider_between_turns, phase_center_turn_rate_deg_s, phase_center_free_after_turn_s,
                                   phase_center_boresight_estimated,
                                   graphic_ambiguity_sigma_m, sdcp_ambiguity_sigma_cycles, slot_timeout_s,
                                   graphic_sigma_m, sdcp_sigma_m, sdcp_correlation_inflation,
                                   sdcp_multipath_sigma_m, sdcp_multipath_tau_s, gate_sigmas, sd_code, sd_code_sigma_m,
                                   code_multipath_sigma_m, code_multipath_tau_s,
                                   elevation_weighting, min_weighting_elevation_deg, min_fix_elevation_deg, ambiguity_resolution,
                                   min_float_s_before_fix, acceptance, hold, hold_variance_cycles2)
}  // namespace visors::nav

namespace visors::dynamics {
NLOHMANN_JSON_SERIALIZE_ENUM(AtmosphereKind, {{AtmosphereKind::kHarrisPriester, "harris-priester"},
                                              {AtmosphereKind::kHarrisPriesterMaximum, "harris-priester-max"},
                                              {AtmosphereKind::kNrlmsise00, "nrlmsise00"}})
NLOHMANN_JSON_SERIALIZE_ENUM(ShadowModel, {{ShadowModel::kNone, "none"},
                                           {ShadowModel::kCylindrical, "cylindrical"},
                                           {ShadowModel::kConical, "conical"}})
void to_json(nlohmann::json& j, const SolarActivity& a) {
  j = {{"f107", a.f107}, {"f107a", a.f107a}, {"ap", a.ap}, {"ap_history", nullptr}};
  if (a.ap_history) j["ap_history"] = *a.ap_history;
}
void from_json(const nlohmann::json& j, SolarActivity& a) {
  j.at("f107").get_to(a.f107);
  j.at("f107a").get_to(a.f107a);
  j.at("ap").get_to(a.ap);
  const nlohmann::json& history = j.at("ap_history");
  if (history.is_null()) a.ap_history.reset();
  else a.ap_history = history.get<std::array<double, 7>>();
}
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(GravityConfig, model, degree, order, allow_embedded_fallback)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DragConfig, enabled, atmosphere, cosine_exponent, density_scale, space_weather,
                                   ap_history, activity, nrlmsise00_coefficients)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SrpConfig, enabled, pressure_1au, shadow)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EarthFrameConfig, eop, refresh_interval)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ForceModelConfig, gravity, drag, srp, sun, moon, earth_frame, empirical_rtn)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SpacecraftProperties, mass, drag_area, cd, srp_area, cr)
}  // namespace visors::dynamics

namespace visors::gnc {
NLOHMANN_JSON_SERIALIZE_ENUM(Spacecraft, {{Spacecraft::kDsc, "dsc"}, {Spacecraft::kOsc, "osc"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StandbyKeepingSettings, check_period_orbits, de_deadband_m, dlambda_threshold_m,
                                   plan_orbits, drag_compensation)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DifferentialDragSettings, baseline_s, settle_s, gain)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(TransferSettings, waypoints, leg_orbits, normal_burns, end_margin_s, max_waypoints,
                                   drag_compensation)
// The burn times as a list of the used entries (least_squares_burns of them).
void to_json(nlohmann::json& j, const ScienceSettings& s) {
  j = {{"geometry", s.geometry},
       {"choose_pole", s.choose_pole},
       {"least_squares_window_s", s.least_squares_window_s},
       {"least_squares_burns_before_s",
        std::vector<double>(s.least_squares_burns_before_s.begin(),
                            s.least_squares_burns_before_s.begin() + s.least_squares_burns)},
       {"least_squares", s.least_squares},
       {"last_burn_velocity_weight_s", s.last_burn_velocity_weight_s},
       {"least_squares_period_s", s.least_squares_period_s},
       {"mpc_period_s", s.mpc_period_s},
       {"mpc", s.mpc},
       {"min_lead_s", s.min_lead_s},
       {"observation_duration_s", s.observation_duration_s},
       {"slew_rate_radps", s.slew_rate_radps},
       {"slew_settle_s", s.slew_settle_s},
       {"drag_drift_nodes", s.drag_drift_nodes},
       {"slew_margin_rad", s.slew_margin_rad}};
}
void from_json(const nlohmann::json& j, ScienceSettings& s) {
  j.at("geometry").get_to(s.geometry);
  j.at("choose_pole").get_to(s.choose_pole);
  j.at("least_squares_window_s").get_to(s.least_squares_window_s);
  const auto burns = j.at("least_squares_burns_before_s").get<std::vector<double>>();
  if (burns.empty() || burns.size() > s.least_squares_burns_before_s.size()) {
    throw std::invalid_argument("least_squares_burns_before_s: 1 to " +
                                std::to_string(s.least_squares_burns_before_s.size()) + " burn times expected");
  }
  s.least_squares_burns_before_s = {};
  std::copy(burns.begin(), burns.end(), s.least_squares_burns_before_s.begin());
  s.least_squares_burns = static_cast<int>(burns.size());
  j.at("least_squares").get_to(s.least_squares);
  j.at("last_burn_velocity_weight_s").get_to(s.last_burn_velocity_weight_s);
  j.at("least_squares_period_s").get_to(s.least_squares_period_s);
  j.at("mpc_period_s").get_to(s.mpc_period_s);
  j.at("mpc").get_to(s.mpc);
  j.at("min_lead_s").get_to(s.min_lead_s);
  j.at("observation_duration_s").get_to(s.observation_duration_s);
  j.at("slew_rate_radps").get_to(s.slew_rate_radps);
  j.at("slew_settle_s").get_to(s.slew_settle_s);
  j.at("drag_drift_nodes").get_to(s.drag_drift_nodes);
  j.at("slew_margin_rad").get_to(s.slew_margin_rad);
}
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(GncConfig, self, active, mass_kg, gravity, standby, standby_keeping, transfer, drag,
                                   science, safety, escape, buffer, burn_latency_s, max_planning_failures,
                                   max_estimate_age_s, maneuver_queue_capacity)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(OnboardNavigationSettings, filter, antenna_arp_body_m, antenna_pco_m, lrf_lever_body_m,
                                   lrf_sigma_m, lrf_bias_m, fuse_laser, peer_wait_s, coast_after_s,
                                   valid_position_sigma_m, valid_velocity_sigma_mps, earth_orientation)
}  // namespace visors::gnc

namespace visors::gnc::files {

nlohmann::json to_json(const ComponentSetup& setup) {
  nlohmann::json component{{"gnc", setup.gnc}};
  if (setup.navigation) {
    component["navigation"] = setup.navigation->settings;
    component["force_models"] = {
        {"config", setup.navigation->force_model}, {"dsc", setup.navigation->dsc}, {"osc", setup.navigation->osc}};
  }
  return component;
}

core::Result<ComponentSetup> component_setup_from_json(const nlohmann::json& component) {
  ComponentSetup setup;
  const char* part = "gnc";
  try {
    if (!component.is_object()) return core::Error{"", "a component's configuration must be a JSON object"};
    component.at("gnc").get_to(setup.gnc);
    part = "navigation";
    if (component.contains("navigation")) {
      NavigationSetup navigation;
      component.at("navigation").get_to(navigation.settings);
      part = "force_models";
      const nlohmann::json& models = component.at("force_models");
      models.at("config").get_to(navigation.force_model);
      models.at("dsc").get_to(navigation.dsc);
      models.at("osc").get_to(navigation.osc);
      setup.navigation = std::move(navigation);
    }
  } catch (const std::exception& e) {
    return core::Error{part, e.what()};
  }
  return setup;
}

core::Result<ComponentSetup> read_component_setup(const std::filesystem::path& file, std::string_view craft) {
  std::ifstream in(file);
  if (!in) return core::Error{file.string(), "cannot be read"};
  const nlohmann::json all = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (all.is_discarded()) return core::Error{file.string(), "is not valid JSON"};
  if (!all.is_object() || !all.contains(craft)) {
    return core::Error{file.string(), "has no component \"" + std::string(craft) + "\" (expected \"dsc\" or \"osc\")"};
  }
  auto setup = component_setup_from_json(all.at(std::string(craft)));
  if (!setup.ok()) {
    return core::Error{file.string(), std::string(craft) + "." + setup.error().describe()};
  }
  return setup;
}

core::Result<RecordInterface> make_component(const ComponentSetup& setup) {
  std::optional<OnboardNavigation> onboard;
  if (setup.navigation) {
    const NavigationSetup& n = *setup.navigation;
    auto dsc = dynamics::files::load_force_model(n.force_model, n.dsc);
    if (!dsc.ok()) return core::Error{"dsc on-board force model", dsc.error().describe()};
    auto osc = dynamics::files::load_force_model(n.force_model, n.osc);
    if (!osc.ok()) return core::Error{"osc on-board force model", osc.error().describe()};
    auto navigation = OnboardNavigation::create(n.settings, setup.gnc.self, std::move(dsc).value(), std::move(osc).value());
    if (!navigation.ok()) return core::Error{"nav." + navigation.error().field, navigation.error().message};
    onboard.emplace(std::move(navigation).value());
  }
  auto component = RecordInterface::create(setup.gnc, std::move(onboard));
  if (!component.ok()) return core::Error{"gnc." + component.error().field, component.error().message};
  return component;
}

}  // namespace visors::gnc::files
