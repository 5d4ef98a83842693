#include "visors/sim/flight_config.hpp"

#include <string>

#include "visors/sim/navigation_setup.hpp"

// JSON forms of the flight configuration structs: each field once, by its name in the struct.
namespace nlohmann {
template <int N>
struct adl_serializer<Eigen::Matrix<double, N, 1>> {
  static void to_json(json& j, const Eigen::Matrix<double, N, 1>& v) {
    j = json::array();
    for (int i = 0; i < N; ++i) j.push_back(v[i]);
  }
  static void from_json(const json& j, Eigen::Matrix<double, N, 1>& v) {
    for (int i = 0; i < N; ++i) v[i] = j.at(static_cast<std::size_t>(i)).get<double>();
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
                                   execution_sigma_floor_mps, freeze_time_s, burn_latency_s)
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
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(GravityConfig, model, degree, order, allow_embedded_fallback)
void to_json(nlohmann::json& j, const DragConfig& d) {
  j = {{"enabled", d.enabled},
       {"atmosphere", d.atmosphere},
       {"cosine_exponent", d.cosine_exponent},
       {"density_scale", d.density_scale},
       {"space_weather", d.space_weather},
       {"ap_history", d.ap_history},
       {"activity", d.activity},
       {"nrlmsise00_coefficients", d.nrlmsise00_coefficients}};
}
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SrpConfig, enabled, pressure_1au, shadow)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EarthFrameConfig, eop, refresh_interval)
void to_json(nlohmann::json& j, const ForceModelConfig& c) {
  j = {{"gravity", c.gravity}, {"drag", c.drag},         {"srp", c.srp},
       {"sun", c.sun},         {"moon", c.moon},         {"earth_frame", c.earth_frame},
       {"empirical_rtn", c.empirical_rtn}};
}
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SpacecraftProperties, mass, drag_area, cd, srp_area, cr)
}  // namespace visors::dynamics

namespace visors::gnc {
NLOHMANN_JSON_SERIALIZE_ENUM(Spacecraft, {{Spacecraft::kDsc, "dsc"}, {Spacecraft::kOsc, "osc"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StandbyKeepingSettings, check_period_orbits, de_deadband_m, dlambda_threshold_m,
                                   plan_orbits, drag_compensation)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DifferentialDragSettings, baseline_s, settle_s, gain)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(TransferSettings, waypoints, leg_orbits, normal_burns, end_margin_s, max_waypoints,
                                   drag_compensation)
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
void to_json(nlohmann::json& j, const GncConfig& c) {
  j = {{"self", c.self},
       {"active", c.active},
       {"mass_kg", c.mass_kg},
       {"gravity", c.gravity},
       {"standby", c.standby},
       {"standby_keeping", c.standby_keeping},
       {"transfer", c.transfer},
       {"drag", c.drag},
       {"science", c.science},
       {"safety", c.safety},
       {"escape", c.escape},
       {"buffer", c.buffer},
       {"burn_latency_s", c.burn_latency_s},
       {"max_planning_failures", c.max_planning_failures},
       {"max_estimate_age_s", c.max_estimate_age_s},
       {"maneuver_queue_capacity", c.maneuver_queue_capacity}};
}
void to_json(nlohmann::json& j, const OnboardNavigationSettings& s) {
  j = {{"filter", s.filter},
       {"antenna_arp_body_m", s.antenna_arp_body_m},
       {"antenna_pco_m", s.antenna_pco_m},
       {"lrf_lever_body_m", s.lrf_lever_body_m},
       {"lrf_sigma_m", s.lrf_sigma_m},
       {"lrf_bias_m", s.lrf_bias_m},
       {"fuse_laser", s.fuse_laser},
       {"peer_wait_s", s.peer_wait_s},
       {"coast_after_s", s.coast_after_s},
       {"valid_position_sigma_m", s.valid_position_sigma_m},
       {"valid_velocity_sigma_mps", s.valid_velocity_sigma_mps},
       {"earth_orientation", s.earth_orientation}};
}
}  // namespace visors::gnc

namespace visors::sim {

gnc::GncConfig flight_gnc_config(const CampaignScenario& s, gnc::Spacecraft craft, bool active) {
  gnc::GncConfig config = s.gnc;
  config.self = craft;
  config.active = active;
  config.mass_kg = craft == gnc::Spacecraft::kDsc ? s.flight.dsc_mass_kg : s.flight.osc_mass_kg;  // what it is told
  return config;
}

dynamics::SpacecraftProperties flight_spacecraft_properties(const FlightKnowledge& k, gnc::Spacecraft craft) {
  dynamics::SpacecraftProperties p;
  p.mass = craft == gnc::Spacecraft::kDsc ? k.dsc_mass_kg : k.osc_mass_kg;
  p.cd = k.cd;
  p.cr = k.cr;
  p.drag_area = k.drag_area_m2;
  p.srp_area = k.srp_area_m2;
  return p;
}

core::Result<nlohmann::json> flight_config_json(const CampaignScenario& s) {
  nlohmann::json out;
  const nlohmann::json force_models = {
      {"config", dynamics::ForceModelConfig::onboard()},
      {"dsc", flight_spacecraft_properties(s.flight, gnc::Spacecraft::kDsc)},
      {"osc", flight_spacecraft_properties(s.flight, gnc::Spacecraft::kOsc)}};
  for (const gnc::Spacecraft craft : {gnc::Spacecraft::kDsc, gnc::Spacecraft::kOsc}) {
    const std::string name = craft == gnc::Spacecraft::kDsc ? "dsc" : "osc";
    nlohmann::json component{{"gnc", flight_gnc_config(s, craft, s.active == name)}};
    if (s.navigation_mode == NavigationMode::kCdgps) {
      auto navigation = onboard_navigation_settings(s);
      if (!navigation.ok()) return navigation.error();
      gnc::OnboardNavigationSettings settings = navigation.value();
      settings.filter.local = craft == gnc::Spacecraft::kDsc ? nav::Craft::kDsc : nav::Craft::kOsc;  // as create() sets it
      component["navigation"] = settings;
      component["force_models"] = force_models;
    }
    out[name] = component;
  }
  return out;
}

}  // namespace visors::sim
