#include "visors/sim/campaign_scenario.hpp"

#include <cmath>
#include <span>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "visors/core/angles.hpp"
#include "visors/core/constants.hpp"
#include "visors/config/toml_fields.hpp"
#include "visors/config/cdgps_settings_toml.hpp"
#include "visors/config/force_model_toml.hpp"

namespace visors::sim {

namespace {

// The commanded target's largest distance from the Sun's centre: the disc's radius is 944-976"
// over the year; beyond 1.25 radii the corona is too faint for the photon sieve.
constexpr double kMaxTargetOffsetArcsec = 1200.0;

using core::Error;
using namespace config::toml_fields;

core::Result<bool> in_range(double value, double lo, double hi, const std::string& field) {
  if (!(value >= lo && value <= hi)) return Error{field, fmt::format("must be in [{}, {}]", lo, hi)};
  return true;
}

// An array of N finite numbers; `fallback` when absent.
template <int N>
core::Result<Eigen::Matrix<double, N, 1>> fixed_vector_at(const toml::table& table, const std::string& section,
                                                         std::string_view key, const Eigen::Matrix<double, N, 1>& fallback) {
  const toml::node* node = table.get(key);
  if (node == nullptr) return fallback;
  const toml::array* array = node->as_array();
  const std::string field = field_name(section, key);
  if (array == nullptr || array->size() != N) return Error{field, fmt::format("must be an array of {} numbers", N)};
  Eigen::Matrix<double, N, 1> out;
  for (std::size_t k = 0; k < N; ++k) {
    const auto value = (*array)[k].value<double>();
    if (!value || !std::isfinite(*value)) return Error{field, fmt::format("must be an array of {} finite numbers", N)};
    out(static_cast<Eigen::Index>(k)) = *value;
  }
  return out;
}

// The least-squares burn times [s before the observation]: an array of 1..kMaxLeastSquaresBurns
// numbers (their order and range are checked with the rest of the GNC configuration).
core::Result<bool> read_burn_times(const toml::table& table, const std::string& section, gnc::ScienceSettings& science) {
  const toml::node* node = table.get("least_squares_burns_before_s");
  if (node == nullptr) return true;
  const std::string field = field_name(section, "least_squares_burns_before_s");
  const toml::array* array = node->as_array();
  const auto capacity = science.least_squares_burns_before_s.size();
  if (array == nullptr || array->empty() || array->size() > capacity) {
    return Error{field, fmt::format("must be an array of 1 to {} numbers", capacity)};
  }
  for (std::size_t k = 0; k < array->size(); ++k) {
    const auto value = (*array)[k].value<double>();
    if (!value || !std::isfinite(*value)) return Error{field, fmt::format("element {} must be a finite number", k)};
    science.least_squares_burns_before_s[k] = *value;
  }
  science.least_squares_burns = static_cast<int>(array->size());
  return true;
}

const toml::table* table_at(const toml::table& root, std::string_view key) { return root.get_as<toml::table>(key); }

// A root table as TOML text, printed from the root so that nested tables keep their prefix.
std::string table_text(std::string_view key, const toml::table& table) {
  toml::table wrapper;
  wrapper.insert(key, table);
  std::ostringstream text;
  text << wrapper;
  return text.str() + "\n";
}

core::Result<bool> read_time(const toml::table& root, CampaignScenario& s) {
  const toml::table* t = table_at(root, "time");
  if (t == nullptr) return true;
  if (auto e = check_keys(*t, "time", {"start_gps", "step_s", "output_step_s", "integration_step_s", "max_duration_s"})) {
    return *e;
  }
  if (t->contains("start_gps")) {
    VISORS_TRY(text, string_at(*t, "time", "start_gps", std::nullopt));
    auto start = core::GpsTime::parse(text, core::TimeScale::kGps);
    if (!start) return Error{"time.start_gps", start.error().message};
    s.t0 = start.value();
  }
  VISORS_TRY(step, number_at(*t, "time", "step_s", s.step_s));
  VISORS_TRY(output, number_at(*t, "time", "output_step_s", s.output_step_s));
  VISORS_TRY(integration, number_at(*t, "time", "integration_step_s", s.integration_step_s));
  VISORS_TRY(max_duration, number_at(*t, "time", "max_duration_s", s.max_duration_s));
  if (auto ok = in_range(step, 0.1, 10.0, "time.step_s"); !ok) return ok.error();
  if (auto ok = in_range(output, step, 3600.0, "time.output_step_s"); !ok) return ok.error();
  if (auto ok = in_range(integration, 0.01, step, "time.integration_step_s"); !ok) return ok.error();
  if (auto ok = in_range(max_duration, step, 3.2e7, "time.max_duration_s"); !ok) return ok.error();
  if (std::abs(std::round(step / integration) * integration - step) > 1e-9) {
    return Error{"time.integration_step_s", "must divide time.step_s"};
  }
  if (std::abs(std::round(output / step) * step - output) > 1e-9) {
    return Error{"time.output_step_s", "must be a multiple of time.step_s"};
  }
  s.step_s = step;
  s.output_step_s = output;
  s.integration_step_s = integration;
  s.max_duration_s = max_duration;
  return true;
}

core::Result<bool> read_chief(const toml::table& root, CampaignScenario& s) {
  const toml::table* c = table_at(root, "chief");
  if (c == nullptr) return true;
  const std::string sec = "chief";
  if (auto e = check_keys(*c, sec, {"a_m", "e", "i_deg", "raan_deg", "argp_deg", "u_deg"})) return *e;
  auto& k = s.chief_mean;
  VISORS_TRY(a, number_at(*c, sec, "a_m", k.a));
  VISORS_TRY(ecc, number_at(*c, sec, "e", k.e));
  VISORS_TRY(i_deg, number_at(*c, sec, "i_deg", k.i / core::kDegToRad));
  VISORS_TRY(raan_deg, number_at(*c, sec, "raan_deg", k.raan / core::kDegToRad));
  VISORS_TRY(argp_deg, number_at(*c, sec, "argp_deg", k.argp / core::kDegToRad));
  VISORS_TRY(u_deg, number_at(*c, sec, "u_deg", (k.argp + k.M) / core::kDegToRad));
  if (auto ok = in_range(a, core::kWgs84SemiMajorAxis + 200e3, core::kWgs84SemiMajorAxis + 2000e3, "chief.a_m"); !ok) {
    return ok.error();
  }
  if (auto ok = in_range(ecc, 0.0, 0.05, "chief.e"); !ok) return ok.error();
  if (auto ok = in_range(i_deg, 1.0, 179.0, "chief.i_deg"); !ok) return ok.error();
  k = astro::KeplerianElements{a, ecc, i_deg * core::kDegToRad, raan_deg * core::kDegToRad, argp_deg * core::kDegToRad,
                               (u_deg - argp_deg) * core::kDegToRad};
  return true;
}

core::Result<bool> read_campaign(const toml::table& root, CampaignScenario& s) {
  if (const toml::table* f = table_at(root, "formation")) {
    if (auto e = check_keys(*f, "formation", {"initial_roe_m"})) return *e;
    VISORS_TRY(roe, fixed_vector_at<6>(*f, "formation", "initial_roe_m", s.initial_roe_m));
    if (roe.cwiseAbs().maxCoeff() > 5000.0) return Error{"formation.initial_roe_m", "must be within 5 km"};
    s.initial_roe_m = roe;
  }
  const toml::table* c = table_at(root, "campaign");
  if (c == nullptr) return true;
  const std::string sec = "campaign";
  if (auto e = check_keys(*c, sec, {"standby_s", "observations", "tail_s", "active", "target_offset_arcsec"})) return *e;
  VISORS_TRY(standby, number_at(*c, sec, "standby_s", s.standby_s));
  VISORS_TRY(observations, integer_at(*c, sec, "observations", s.observations));
  VISORS_TRY(tail, number_at(*c, sec, "tail_s", s.tail_s));
  VISORS_TRY(active, string_at(*c, sec, "active", s.active));
  const Eigen::Vector2d offset_arcsec = s.target_offset_rad / core::kArcsecToRad;
  VISORS_TRY(target, fixed_vector_at<2>(*c, sec, "target_offset_arcsec", offset_arcsec));
  if (auto ok = in_range(standby, 0.0, 3.2e7, "campaign.standby_s"); !ok) return ok.error();
  if (observations < 0 || observations > 1000) return Error{"campaign.observations", "must be in [0, 1000]"};
  if (auto ok = in_range(tail, 0.0, 3.2e7, "campaign.tail_s"); !ok) return ok.error();
  if (active != "osc" && active != "dsc") return Error{"campaign.active", "must be \"osc\" or \"dsc\""};
  if (target.norm() > kMaxTargetOffsetArcsec) {
    return Error{"campaign.target_offset_arcsec", fmt::format("must be within {} arcsec of the Sun's centre", kMaxTargetOffsetArcsec)};
  }
  // A ground command, not a truth parameter: the flight software aims at it, the truth scores
  // against it.
  s.target_offset_rad = target * core::kArcsecToRad;
  s.gnc.science.geometry.target_offset_rad = s.target_offset_rad;
  s.standby_s = standby;
  s.observations = static_cast<int>(observations);
  s.tail_s = tail;
  s.active = active;
  return true;
}

core::Result<bool> read_navigation(const toml::table& root, CampaignScenario& s) {
  const toml::table* n = table_at(root, "navigation");
  if (n == nullptr) return true;
  const std::string sec = "navigation";
  if (auto e = check_keys(*n, sec, {"mode", "relative_position_m", "relative_velocity_mps", "absolute_position_m",
                                    "absolute_velocity_mps", "correlation_time_s"})) {
    return *e;
  }
  VISORS_TRY(mode, string_at(*n, sec, "mode", s.navigation_mode == NavigationMode::kCdgps ? "cdgps" : "ideal"));
  if (mode != "ideal" && mode != "cdgps") return Error{"navigation.mode", "must be \"cdgps\" or \"ideal\""};
  s.navigation_mode = mode == "cdgps" ? NavigationMode::kCdgps : NavigationMode::kIdeal;
  auto& v = s.navigation;
  VISORS_TRY(rp, number_at(*n, sec, "relative_position_m", v.relative_position_m));
  VISORS_TRY(rv, number_at(*n, sec, "relative_velocity_mps", v.relative_velocity_mps));
  VISORS_TRY(ap, number_at(*n, sec, "absolute_position_m", v.absolute_position_m));
  VISORS_TRY(av, number_at(*n, sec, "absolute_velocity_mps", v.absolute_velocity_mps));
  VISORS_TRY(tau, number_at(*n, sec, "correlation_time_s", v.correlation_time_s));
  if (auto ok = in_range(rp, 0.0, 100.0, "navigation.relative_position_m"); !ok) return ok.error();
  if (auto ok = in_range(rv, 0.0, 1.0, "navigation.relative_velocity_mps"); !ok) return ok.error();
  if (auto ok = in_range(ap, 0.0, 1e4, "navigation.absolute_position_m"); !ok) return ok.error();
  if (auto ok = in_range(av, 0.0, 10.0, "navigation.absolute_velocity_mps"); !ok) return ok.error();
  if (auto ok = in_range(tau, 1.0, 1e6, "navigation.correlation_time_s"); !ok) return ok.error();
  v = NavigationErrorSettings{rp, rv, ap, av, tau};
  return true;
}

// The [nav] table (the on-board filter's tunables): checked against the filter's defaults now,
// kept as text for the set-up (which applies it over the receiver-derived settings) and for
// scenario.toml.
core::Result<bool> read_nav_tunables(const toml::table& root, CampaignScenario& s) {
  const toml::table* nav_table = table_at(root, "nav");
  if (nav_table == nullptr) return true;
  nav::CdgpsSettings check;
  if (auto ok = config::read_cdgps_settings(root, check); !ok) return ok.error();
  s.nav_toml = table_text("nav", *nav_table);
  return true;
}

core::Result<bool> read_propulsion(const toml::table& root, CampaignScenario& s) {
  const toml::table* p = table_at(root, "propulsion");
  if (p == nullptr) return true;
  const std::string sec = "propulsion";
  if (auto e = check_keys(*p, sec, {"magnitude_sigma", "magnitude_bias_sigma", "direction_sigma_deg", "isp_s", "isp_sigma_s"})) {
    return *e;
  }
  auto& v = s.propulsion;
  VISORS_TRY(mag, number_at(*p, sec, "magnitude_sigma", v.magnitude_sigma));
  VISORS_TRY(bias, number_at(*p, sec, "magnitude_bias_sigma", v.magnitude_bias_sigma));
  VISORS_TRY(dir, number_at(*p, sec, "direction_sigma_deg", v.direction_sigma_rad / core::kDegToRad));
  VISORS_TRY(isp, number_at(*p, sec, "isp_s", v.isp_s));
  VISORS_TRY(isp_sigma, number_at(*p, sec, "isp_sigma_s", v.isp_sigma_s));
  v.magnitude_sigma = mag;
  v.magnitude_bias_sigma = bias;
  v.direction_sigma_rad = dir * core::kDegToRad;
  v.isp_s = isp;
  v.isp_sigma_s = isp_sigma;
  if (auto ok = v.validate(); !ok) return Error{"propulsion." + ok.error().field, ok.error().message};
  return true;
}

// [geometry]: the truth geometry errors (sim/spacecraft_geometry.hpp), lengths in m, the pointing
// error in arcsec.
core::Result<bool> read_geometry(const toml::table& root, CampaignScenario& s) {
  const toml::table* t = table_at(root, "geometry");
  if (t == nullptr) return true;
  const std::string sec = "geometry";
  if (auto e = check_keys(*t, sec, {"com_variation_sigma_m", "com_knowledge_error_m", "payload_position_sigma_m",
                                    "payload_pointing_sigma_arcsec", "phase_center_knowledge_sigma_m"})) {
    return *e;
  }
  GeometrySettings& g = s.geometry;
  VISORS_TRY(variation, number_at(*t, sec, "com_variation_sigma_m", g.com_sigma_m));
  VISORS_TRY(knowledge, number_at(*t, sec, "com_knowledge_error_m", g.com_knowledge_error_m));
  VISORS_TRY(payload, number_at(*t, sec, "payload_position_sigma_m", g.payload_position_sigma_m));
  VISORS_TRY(pointing, number_at(*t, sec, "payload_pointing_sigma_arcsec", g.payload_pointing_sigma_rad / core::kArcsecToRad));
  VISORS_TRY(phase_center, number_at(*t, sec, "phase_center_knowledge_sigma_m", g.phase_center_knowledge_sigma_m));
  if (auto ok = in_range(variation, 0.0, 1.0, "geometry.com_variation_sigma_m"); !ok) return ok.error();
  if (auto ok = in_range(knowledge, 0.0, 1.0, "geometry.com_knowledge_error_m"); !ok) return ok.error();
  if (auto ok = in_range(payload, 0.0, 1.0, "geometry.payload_position_sigma_m"); !ok) return ok.error();
  if (auto ok = in_range(pointing, 0.0, 3600.0, "geometry.payload_pointing_sigma_arcsec"); !ok) return ok.error();
  if (auto ok = in_range(phase_center, 0.0, 0.1, "geometry.phase_center_knowledge_sigma_m"); !ok) return ok.error();
  g.com_sigma_m = variation;
  g.com_knowledge_error_m = knowledge;
  g.payload_position_sigma_m = payload;
  g.payload_pointing_sigma_rad = pointing * core::kArcsecToRad;
  g.phase_center_knowledge_sigma_m = phase_center;
  return true;
}

// [attitude]: the bus ADCS of both spacecraft, truth (sim/adcs_model.hpp): rate in deg/s, errors
// in arcsec per body axis, correlation times in s.
core::Result<bool> read_attitude(const toml::table& root, CampaignScenario& s) {
  const toml::table* t = table_at(root, "attitude");
  if (t == nullptr) return true;
  const std::string sec = "attitude";
  if (auto e = check_keys(*t, sec, {"slew_rate_deg_s", "pointing_sigma_arcsec", "pointing_tau_s", "jitter_sigma_arcsec",
                                    "knowledge_sigma_arcsec", "knowledge_tau_s", "calibration_yaw_deg", "calibration_hold_s",
                                    "calibration_period_s", "calibration_first_s", "calibration_margin_s"})) {
    return *e;
  }
  AdcsSettings& a = s.adcs;
  constexpr double arcsec = core::kArcsecToRad;
  VISORS_TRY(rate, number_at(*t, sec, "slew_rate_deg_s", a.slew_rate_radps / core::kDegToRad));
  VISORS_TRY(pointing, vector3_at(*t, sec, "pointing_sigma_arcsec", Eigen::Vector3d(a.pointing_sigma_rad / arcsec)));
  VISORS_TRY(pointing_tau, number_at(*t, sec, "pointing_tau_s", a.pointing_tau_s));
  VISORS_TRY(jitter, vector3_at(*t, sec, "jitter_sigma_arcsec", Eigen::Vector3d(a.jitter_sigma_rad / arcsec)));
  VISORS_TRY(knowledge, vector3_at(*t, sec, "knowledge_sigma_arcsec", Eigen::Vector3d(a.knowledge_sigma_rad / arcsec)));
  VISORS_TRY(knowledge_tau, number_at(*t, sec, "knowledge_tau_s", a.knowledge_tau_s));
  a.slew_rate_radps = rate * core::kDegToRad;
  a.pointing_sigma_rad = pointing * arcsec;
  a.pointing_tau_s = pointing_tau;
  a.jitter_sigma_rad = jitter * arcsec;
  a.knowledge_sigma_rad = knowledge * arcsec;
  a.knowledge_tau_s = knowledge_tau;
  if (auto ok = a.validate(); !ok) return Error{"attitude." + ok.error().field, ok.error().message};
  CalibrationYaw& c = s.calibration_yaw;
  VISORS_TRY(yaw, number_at(*t, sec, "calibration_yaw_deg", c.yaw_rad / core::kDegToRad));
  VISORS_TRY(hold, number_at(*t, sec, "calibration_hold_s", c.hold_s));
  VISORS_TRY(period, number_at(*t, sec, "calibration_period_s", c.period_s));
  VISORS_TRY(first, number_at(*t, sec, "calibration_first_s", c.first_s));
  VISORS_TRY(margin, number_at(*t, sec, "calibration_margin_s", c.margin_s));
  c = CalibrationYaw{yaw * core::kDegToRad, hold, period, first, margin};
  AttitudeSettings attitude{.slew_rate_radps = a.slew_rate_radps, .settling_s = 0.0, .calibration = c};
  if (auto ok = attitude.validate(); !ok) {
    static constexpr const char* kKeys[][2] = {{"calibration.yaw_rad", "calibration_yaw_deg"}, {"calibration.hold_s", "calibration_hold_s"},
                                               {"calibration.period_s", "calibration_period_s"}, {"calibration.first_s", "calibration_first_s"},
                                               {"calibration.margin_s", "calibration_margin_s"}};
    for (const auto& [field, key] : kKeys) {
      if (ok.error().field == field) return Error{sec + "." + key, ok.error().message};
    }
    return Error{sec + "." + ok.error().field, ok.error().message};
  }
  return true;
}

// [clock]: the host computers' time at tone, truth (sim/host_clock.hpp): PPS error in ns,
// oscillator frequency error in ppm.
core::Result<bool> read_clock(const toml::table& root, CampaignScenario& s) {
  const toml::table* t = table_at(root, "clock");
  if (t == nullptr) return true;
  const std::string sec = "clock";
  if (auto e = check_keys(*t, sec, {"pps_sigma_ns", "oscillator_sigma_ppm"})) return *e;
  HostClockSettings& c = s.host_clock;
  VISORS_TRY(pps, number_at(*t, sec, "pps_sigma_ns", c.pps_sigma_s * 1e9));
  VISORS_TRY(oscillator, number_at(*t, sec, "oscillator_sigma_ppm", c.oscillator_sigma * 1e6));
  c.pps_sigma_s = pps * 1e-9;
  c.oscillator_sigma = oscillator * 1e-6;
  if (auto ok = c.validate(); !ok) return Error{"clock." + ok.error().field, ok.error().message};
  return true;
}

core::Result<bool> read_spacecraft(const toml::table& root, const std::string& sec, SpacecraftSettings& v) {
  const toml::table* t = table_at(root, sec);
  if (t == nullptr) return true;
  if (auto e = check_keys(*t, sec, {"mass_kg", "propellant_kg", "cd", "cr", "srp_area_m2", "mass_sigma_kg", "cd_sigma", "cr_sigma"})) {
    return *e;
  }
  VISORS_TRY(mass, number_at(*t, sec, "mass_kg", v.mass_kg));
  VISORS_TRY(propellant, number_at(*t, sec, "propellant_kg", v.propellant_kg));
  VISORS_TRY(cd, number_at(*t, sec, "cd", v.cd));
  VISORS_TRY(cr, number_at(*t, sec, "cr", v.cr));
  VISORS_TRY(area, number_at(*t, sec, "srp_area_m2", v.srp_area_m2));
  VISORS_TRY(mass_sigma, number_at(*t, sec, "mass_sigma_kg", v.mass_sigma_kg));
  VISORS_TRY(cd_sigma, number_at(*t, sec, "cd_sigma", v.cd_sigma));
  VISORS_TRY(cr_sigma, number_at(*t, sec, "cr_sigma", v.cr_sigma));
  if (auto ok = in_range(mass, 0.1, 1000.0, sec + ".mass_kg"); !ok) return ok.error();
  if (auto ok = in_range(propellant, 0.0, 0.9 * mass, sec + ".propellant_kg"); !ok) return ok.error();
  if (auto ok = in_range(cd, 0.0, 5.0, sec + ".cd"); !ok) return ok.error();
  if (auto ok = in_range(cr, 0.0, 2.0, sec + ".cr"); !ok) return ok.error();
  if (auto ok = in_range(area, 0.0, 10.0, sec + ".srp_area_m2"); !ok) return ok.error();
  // At most a fifth of the nominal: the draw is clamped at 5 sigma, so the true value stays >= 0.
  if (auto ok = in_range(mass_sigma, 0.0, 0.2 * mass, sec + ".mass_sigma_kg"); !ok) return ok.error();
  if (auto ok = in_range(cd_sigma, 0.0, 0.2 * cd, sec + ".cd_sigma"); !ok) return ok.error();
  if (auto ok = in_range(cr_sigma, 0.0, 0.2 * cr, sec + ".cr_sigma"); !ok) return ok.error();
  v = SpacecraftSettings{mass, propellant, cd, cr, area, mass_sigma, cd_sigma, cr_sigma};
  return true;
}

// [flight]: what the flight software is told of both spacecraft.
core::Result<bool> read_flight_knowledge(const toml::table& root, CampaignScenario& s) {
  const toml::table* t = table_at(root, "flight");
  if (t == nullptr) return true;
  const std::string sec = "flight";
  if (auto e = check_keys(*t, sec, {"dsc_mass_kg", "osc_mass_kg", "cd", "cr", "drag_area_m2", "srp_area_m2", "eop_file",
                                    "antenna_arp_body_m", "antenna_pco_m", "lrf_lever_body_m", "lrf_sigma_m", "lrf_bias_m"})) {
    return *e;
  }
  FlightKnowledge& k = s.flight;
  VISORS_TRY(eop_file, string_at(*t, sec, "eop_file", k.eop_file));
  k.eop_file = eop_file;
  VISORS_TRY(arp, vector3_at(*t, sec, "antenna_arp_body_m", k.antenna_arp_body_m));
  VISORS_TRY(lrf_lever, vector3_at(*t, sec, "lrf_lever_body_m", k.lrf_lever_body_m));
  if (arp.norm() > 1.0) return Error{"flight.antenna_arp_body_m", "must be within 1 m of the centre of mass"};
  if (lrf_lever.norm() > 1.0) return Error{"flight.lrf_lever_body_m", "must be within 1 m of the centre of mass"};
  k.antenna_arp_body_m = arp;
  k.lrf_lever_body_m = lrf_lever;
  const struct {
    const char* key;
    double* value;
    double low, high;
  } fields[] = {{"dsc_mass_kg", &k.dsc_mass_kg, 0.1, 1000.0}, {"osc_mass_kg", &k.osc_mass_kg, 0.1, 1000.0},
                {"cd", &k.cd, 0.0, 5.0},                       {"cr", &k.cr, 0.0, 2.0},
                {"drag_area_m2", &k.drag_area_m2, 0.0, 10.0},   {"srp_area_m2", &k.srp_area_m2, 0.0, 10.0},
                {"antenna_pco_m", &k.antenna_pco_m, 0.0, 0.5},  {"lrf_sigma_m", &k.lrf_sigma_m, 1e-6, 1.0},
                {"lrf_bias_m", &k.lrf_bias_m, -1.0, 1.0}};
  for (const auto& f : fields) {
    VISORS_TRY(value, number_at(*t, sec, f.key, *f.value));
    if (auto ok = in_range(value, f.low, f.high, sec + "." + f.key); !ok) return ok.error();
    *f.value = value;
  }
  return true;
}

core::Result<bool> read_links_and_faults(const toml::table& root, CampaignScenario& s) {
  if (const toml::table* c = table_at(root, "crosslink")) {
    if (auto e = check_keys(*c, "crosslink", {"delay_s", "drop_probability"})) return *e;
    VISORS_TRY(delay, number_at(*c, "crosslink", "delay_s", s.crosslink_delay_s));
    VISORS_TRY(drop, number_at(*c, "crosslink", "drop_probability", s.crosslink_drop_probability));
    if (auto ok = in_range(delay, 0.0, 5.0, "crosslink.delay_s"); !ok) return ok.error();
    if (auto ok = in_range(drop, 0.0, 1.0, "crosslink.drop_probability"); !ok) return ok.error();
    s.crosslink_delay_s = delay;
    s.crosslink_drop_probability = drop;
  }
  if (const toml::table* f = table_at(root, "fault")) {
    if (auto e = check_keys(*f, "fault", {"impulse_t_s", "impulse_dv_rtn_mps", "non_gnc_fault_t_s", "gps_outage_t_s",
                                          "gps_outage_s", "crosslink_loss_t_s", "crosslink_loss_s", "safe_mode_t_s",
                                          "safe_mode_s", "garbage_t_s", "garbage_s", "thruster_failure_t_s",
                                          "clock_jump_t_s", "clock_jump_m"})) {
      return *e;
    }
    VISORS_TRY(t, number_at(*f, "fault", "impulse_t_s", s.fault.impulse_t_s));
    VISORS_TRY(dv, vector3_at(*f, "fault", "impulse_dv_rtn_mps", s.fault.impulse_dv_rtn_mps));
    VISORS_TRY(non_gnc, number_at(*f, "fault", "non_gnc_fault_t_s", s.fault.non_gnc_fault_t_s));
    if (dv.norm() > 1.0) return Error{"fault.impulse_dv_rtn_mps", "must be below 1 m/s"};
    FaultSettings fault = s.fault;
    fault.impulse_t_s = t;
    fault.impulse_dv_rtn_mps = dv;
    fault.non_gnc_fault_t_s = non_gnc;
    for (auto [window, name] : {std::pair{&fault.gps_outage, "gps_outage"}, std::pair{&fault.crosslink_loss, "crosslink_loss"},
                                std::pair{&fault.safe_mode, "safe_mode"}, std::pair{&fault.garbage, "garbage"}}) {
      const std::string start_key = std::string(name) + "_t_s", length_key = std::string(name) + "_s";
      VISORS_TRY(start, number_at(*f, "fault", start_key, window->start_s));
      VISORS_TRY(length, number_at(*f, "fault", length_key, window->duration_s));
      if (auto ok = in_range(length, 0.0, 1e6, "fault." + length_key); !ok) return ok.error();
      *window = FaultWindow{start, length};
    }
    VISORS_TRY(thruster, number_at(*f, "fault", "thruster_failure_t_s", fault.thruster_failure_t_s));
    VISORS_TRY(jump_t, number_at(*f, "fault", "clock_jump_t_s", fault.clock_jump_t_s));
    VISORS_TRY(jump_m, number_at(*f, "fault", "clock_jump_m", fault.clock_jump_m));
    if (auto ok = in_range(jump_m, -1e7, 1e7, "fault.clock_jump_m"); !ok) return ok.error();
    fault.thruster_failure_t_s = thruster;
    fault.clock_jump_t_s = jump_t;
    fault.clock_jump_m = jump_m;
    s.fault = fault;
  }
  return true;
}

core::Result<bool> read_gnc(const toml::table& root, CampaignScenario& s) {
  const toml::table* g = table_at(root, "gnc");
  if (g == nullptr) return true;
  const std::string sec = "gnc";
  if (auto e = check_keys(*g, sec, {"standby_de_deadband_m", "standby_dlambda_threshold_m", "transfer_leg_orbits",
                                    "mpc_period_s", "least_squares_window_s", "safety_epsilon_m", "safety_q_sigma",
                                    "safety_horizon_orbits", "safety_check_period_s", "escape_da_target_m",
                                    "north", "least_squares_burns_before_s", "drag_compensation"})) {
    return *e;
  }
  auto& c = s.gnc;
  VISORS_TRY(de, number_at(*g, sec, "standby_de_deadband_m", c.standby_keeping.de_deadband_m));
  VISORS_TRY(dl, number_at(*g, sec, "standby_dlambda_threshold_m", c.standby_keeping.dlambda_threshold_m));
  VISORS_TRY(leg, number_at(*g, sec, "transfer_leg_orbits", c.transfer.leg_orbits));
  VISORS_TRY(mpc, number_at(*g, sec, "mpc_period_s", c.science.mpc_period_s));
  VISORS_TRY(ls, number_at(*g, sec, "least_squares_window_s", c.science.least_squares_window_s));
  VISORS_TRY(eps, number_at(*g, sec, "safety_epsilon_m", c.safety.epsilon_m));
  VISORS_TRY(q, number_at(*g, sec, "safety_q_sigma", c.safety.q_sigma));
  VISORS_TRY(horizon, number_at(*g, sec, "safety_horizon_orbits", c.safety.horizon_orbits));
  VISORS_TRY(period, number_at(*g, sec, "safety_check_period_s", c.safety.check_period_s));
  VISORS_TRY(da, number_at(*g, sec, "escape_da_target_m", c.escape.da_target_m));
  VISORS_TRY(north, bool_at(*g, sec, "north", c.science.geometry.north));
  VISORS_TRY(drag, bool_at(*g, sec, "drag_compensation", c.transfer.drag_compensation));
  c.standby_keeping.de_deadband_m = de;
  c.standby_keeping.dlambda_threshold_m = dl;
  c.transfer.leg_orbits = leg;
  c.science.mpc_period_s = mpc;
  c.science.least_squares_window_s = ls;
  c.safety.epsilon_m = eps;
  c.safety.q_sigma = q;
  c.safety.horizon_orbits = horizon;
  c.safety.check_period_s = period;
  c.escape.da_target_m = da;
  c.science.geometry.north = north;
  c.transfer.drag_compensation = drag;
  c.standby_keeping.drag_compensation = drag;
  if (auto ok = read_burn_times(*g, sec, c.science); !ok) return ok.error();
  if (auto ok = gnc::validate(c); !ok) return Error{"gnc (" + ok.error().field + ")", ok.error().message};
  return true;
}

}  // namespace

CampaignScenario default_campaign() {
  CampaignScenario s;
  s.t0 = core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kGps).value();
  // Mission test case (paper, test-case table): a = R_E + 500 km, e = 0.004, i = 97.8 deg,
  // RAAN = 157.5 deg (LTAN 10:00 on 2024-10-01), u(t0) = 0; argp 90 deg puts e along ey.
  s.chief_mean = astro::KeplerianElements{core::kWgs84SemiMajorAxis + 500e3, 0.004, 97.8 * core::kDegToRad,
                                          157.5 * core::kDegToRad, 90.0 * core::kDegToRad, -90.0 * core::kDegToRad};
  s.initial_roe_m << 0.0, 0.0, 0.0, 200.0, 0.0, 200.0;  // the standby orbit
  s.dsc.mass_kg = 11.35;
  s.dsc.propellant_kg = 0.378;
  s.osc.mass_kg = 10.62;
  s.osc.propellant_kg = 0.205;
  // An active region 310" east and 240" south of the disc centre (0.41 solar radii): the
  // telescope looks at a commanded point of the disc, not at its centre.
  s.target_offset_rad = Eigen::Vector2d(310.0, -240.0) * core::kArcsecToRad;
  s.gnc.science.geometry.target_offset_rad = s.target_offset_rad;
  // The real sky's receiver errors (docs/truth-and-knowledge.md "Receiver errors"): noise growing
  // as 1 / sin(elevation) and correlated code and carrier multipath; the receiver model's own
  // defaults (sim/gps_receiver.hpp) stay white for its unit tests.
  s.gnss.receiver.elevation_dependent_noise = true;
  s.gnss.receiver.phase_multipath_m = 0.002;
  s.gnss.receiver.code_multipath_m = 0.3;
  s.gnss.receiver.multipath_tau_s = 60.0;
  return s;
}

std::int64_t step_at(double t_s, double step_s) {
  return t_s >= 0.0 ? static_cast<std::int64_t>(std::llround(t_s / step_s)) : -1;
}

core::Result<CampaignScenario> campaign_from_toml(const std::string& text) {
  auto parsed = parse(text);
  if (!parsed.ok()) return parsed.error();
  const toml::table& root = parsed.value();
  if (auto e = check_keys(root, "", {"name", "seed", "time", "chief", "formation", "campaign", "navigation", "propulsion",
                                     "dsc", "osc", "flight", "geometry", "attitude", "clock", "crosslink", "forces", "gnc", "fault", "gnss", "nav"})) {
    return *e;
  }
  CampaignScenario s = default_campaign();
  VISORS_TRY(name, string_at(root, "", "name", s.name));
  VISORS_TRY(seed, integer_at(root, "", "seed", static_cast<std::int64_t>(s.seed)));
  if (seed < 0) return Error{"seed", "must be >= 0"};
  s.name = name;
  s.seed = static_cast<std::uint64_t>(seed);
  for (auto* reader : {&read_time, &read_chief, &read_campaign, &read_navigation, &read_nav_tunables, &read_propulsion,
                       &read_geometry, &read_attitude, &read_clock, &read_links_and_faults, &read_gnc}) {
    if (auto ok = reader(root, s); !ok) return ok.error();
  }
  if (auto ok = read_spacecraft(root, "dsc", s.dsc); !ok) return ok.error();
  if (auto ok = read_spacecraft(root, "osc", s.osc); !ok) return ok.error();
  if (auto ok = read_flight_knowledge(root, s); !ok) return ok.error();
  if (auto ok = read_gnss_settings(root, s.gnss); !ok) return ok.error();
  if (const toml::table* forces = table_at(root, "forces")) {
    auto config = config::force_model_config_from_toml(forces, "forces");
    if (!config.ok()) return config.error();
    s.forces = config.value();
    s.forces_toml = table_text("forces", *forces);
  }
  return s;
}

std::string campaign_to_toml(const CampaignScenario& s) {
  const auto deg = [](double rad) { return rad / core::kDegToRad; };
  const auto& k = s.chief_mean;
  const auto& n = s.navigation;
  const auto& p = s.propulsion;
  const auto& g = s.gnc;
  const auto spacecraft = [](const char* name, const SpacecraftSettings& v) {
    return fmt::format("[{}]\nmass_kg = {:.17g}\npropellant_kg = {:.17g}\ncd = {:.17g}\ncr = {:.17g}\nsrp_area_m2 = {:.17g}\nmass_sigma_kg = {:.17g}\ncd_sigma = {:.17g}\ncr_sigma = {:.17g}\n\n",
                       name, v.mass_kg, v.propellant_kg, v.cd, v.cr, v.srp_area_m2, v.mass_sigma_kg, v.cd_sigma, v.cr_sigma);
  };
  std::string out = fmt::format("# Resolved scenario of this run (every default written out).\nname = \"{}\"\nseed = {}\n\n", s.name, s.seed);
  out += fmt::format("[time]\nstart_gps = \"{}\"\nstep_s = {:.17g}\noutput_step_s = {:.17g}\nintegration_step_s = {:.17g}\nmax_duration_s = {:.17g}\n\n",
                     s.t0.format(core::TimeScale::kGps, 3), s.step_s, s.output_step_s, s.integration_step_s, s.max_duration_s);
  out += fmt::format("[chief]  # mean elements at the start\na_m = {:.17g}\ne = {:.17g}\ni_deg = {:.17g}\nraan_deg = {:.17g}\nargp_deg = {:.17g}\nu_deg = {:.17g}\n\n",
                     k.a, k.e, deg(k.i), deg(k.raan), deg(k.argp), deg(k.argp + k.M));
  out += fmt::format("[formation]\ninitial_roe_m = [{:.17g}, {:.17g}, {:.17g}, {:.17g}, {:.17g}, {:.17g}]\n\n",
                     s.initial_roe_m(0), s.initial_roe_m(1), s.initial_roe_m(2), s.initial_roe_m(3), s.initial_roe_m(4),
                     s.initial_roe_m(5));
  const Eigen::Vector2d target_arcsec = s.target_offset_rad / core::kArcsecToRad;
  out += fmt::format("[campaign]\nstandby_s = {:.17g}\nobservations = {}\ntail_s = {:.17g}\nactive = \"{}\"\ntarget_offset_arcsec = [{:.17g}, {:.17g}]\n\n",
                     s.standby_s, s.observations, s.tail_s, s.active, target_arcsec.x(), target_arcsec.y());
  out += fmt::format("[navigation]\nmode = \"{}\"\nrelative_position_m = {:.17g}\nrelative_velocity_mps = {:.17g}\nabsolute_position_m = {:.17g}\nabsolute_velocity_mps = {:.17g}\ncorrelation_time_s = {:.17g}\n\n",
                     s.navigation_mode == NavigationMode::kCdgps ? "cdgps" : "ideal", n.relative_position_m,
                     n.relative_velocity_mps, n.absolute_position_m, n.absolute_velocity_mps, n.correlation_time_s);
  out += fmt::format("[propulsion]\nmagnitude_sigma = {:.17g}\nmagnitude_bias_sigma = {:.17g}\ndirection_sigma_deg = {:.17g}\nisp_s = {:.17g}\nisp_sigma_s = {:.17g}\n\n",
                     p.magnitude_sigma, p.magnitude_bias_sigma, deg(p.direction_sigma_rad), p.isp_s, p.isp_sigma_s);
  out += spacecraft("dsc", s.dsc);
  out += spacecraft("osc", s.osc);
  const FlightKnowledge& told = s.flight;
  const auto vec = [](const Eigen::Vector3d& x) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", x.x(), x.y(), x.z()); };
  out += fmt::format("[flight]\ndsc_mass_kg = {:.17g}\nosc_mass_kg = {:.17g}\ncd = {:.17g}\ncr = {:.17g}\ndrag_area_m2 = {:.17g}\nsrp_area_m2 = {:.17g}\neop_file = \"{}\"\n",
                     told.dsc_mass_kg, told.osc_mass_kg, told.cd, told.cr, told.drag_area_m2, told.srp_area_m2, told.eop_file);
  out += fmt::format("antenna_arp_body_m = {}\nantenna_pco_m = {:.17g}\nlrf_lever_body_m = {}\nlrf_sigma_m = {:.17g}\nlrf_bias_m = {:.17g}\n\n",
                     vec(told.antenna_arp_body_m), told.antenna_pco_m, vec(told.lrf_lever_body_m), told.lrf_sigma_m, told.lrf_bias_m);
  out += fmt::format("[geometry]\ncom_variation_sigma_m = {:.17g}\ncom_knowledge_error_m = {:.17g}\npayload_position_sigma_m = {:.17g}\npayload_pointing_sigma_arcsec = {:.17g}\nphase_center_knowledge_sigma_m = {:.17g}\n\n",
                     s.geometry.com_sigma_m, s.geometry.com_knowledge_error_m, s.geometry.payload_position_sigma_m,
                     s.geometry.payload_pointing_sigma_rad / core::kArcsecToRad, s.geometry.phase_center_knowledge_sigma_m);
  const AdcsSettings& a = s.adcs;
  const auto arcsec3 = [](const Eigen::Vector3d& rad) {
    const Eigen::Vector3d x = rad / core::kArcsecToRad;
    return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", x.x(), x.y(), x.z());
  };
  out += fmt::format("[attitude]\nslew_rate_deg_s = {:.17g}\npointing_sigma_arcsec = {}\npointing_tau_s = {:.17g}\njitter_sigma_arcsec = {}\nknowledge_sigma_arcsec = {}\nknowledge_tau_s = {:.17g}\n",
                     deg(a.slew_rate_radps), arcsec3(a.pointing_sigma_rad), a.pointing_tau_s, arcsec3(a.jitter_sigma_rad),
                     arcsec3(a.knowledge_sigma_rad), a.knowledge_tau_s);
  const CalibrationYaw& c = s.calibration_yaw;
  out += fmt::format("calibration_yaw_deg = {:.17g}\ncalibration_hold_s = {:.17g}\ncalibration_period_s = {:.17g}\ncalibration_first_s = {:.17g}\ncalibration_margin_s = {:.17g}\n\n",
                     deg(c.yaw_rad), c.hold_s, c.period_s, c.first_s, c.margin_s);
  out += fmt::format("[clock]\npps_sigma_ns = {:.17g}\noscillator_sigma_ppm = {:.17g}\n\n", s.host_clock.pps_sigma_s * 1e9,
                     s.host_clock.oscillator_sigma * 1e6);
  out += fmt::format("[crosslink]\ndelay_s = {:.17g}\ndrop_probability = {:.17g}\n\n", s.crosslink_delay_s, s.crosslink_drop_probability);
  out += fmt::format("[gnc]\nstandby_de_deadband_m = {:.17g}\nstandby_dlambda_threshold_m = {:.17g}\ntransfer_leg_orbits = {:.17g}\nmpc_period_s = {:.17g}\nleast_squares_window_s = {:.17g}\nsafety_epsilon_m = {:.17g}\nsafety_q_sigma = {:.17g}\nsafety_horizon_orbits = {:.17g}\nsafety_check_period_s = {:.17g}\nescape_da_target_m = {:.17g}\nnorth = {}\ndrag_compensation = {}\nleast_squares_burns_before_s = [{:.17g}]\n\n",
                     g.standby_keeping.de_deadband_m, g.standby_keeping.dlambda_threshold_m, g.transfer.leg_orbits,
                     g.science.mpc_period_s, g.science.least_squares_window_s, g.safety.epsilon_m, g.safety.q_sigma,
                     g.safety.horizon_orbits, g.safety.check_period_s, g.escape.da_target_m, g.science.geometry.north,
                     g.transfer.drag_compensation, fmt::join(std::span(g.science.least_squares_burns_before_s.data(),
                                         static_cast<std::size_t>(g.science.least_squares_burns)),
                               ", "));
  out += fmt::format("[fault]\nimpulse_t_s = {:.17g}\nimpulse_dv_rtn_mps = [{:.17g}, {:.17g}, {:.17g}]\nnon_gnc_fault_t_s = {:.17g}\n",
                     s.fault.impulse_t_s, s.fault.impulse_dv_rtn_mps(0), s.fault.impulse_dv_rtn_mps(1),
                     s.fault.impulse_dv_rtn_mps(2), s.fault.non_gnc_fault_t_s);
  for (auto [window, name] : {std::pair{&s.fault.gps_outage, "gps_outage"}, std::pair{&s.fault.crosslink_loss, "crosslink_loss"},
                              std::pair{&s.fault.safe_mode, "safe_mode"}, std::pair{&s.fault.garbage, "garbage"}}) {
    out += fmt::format("{}_t_s = {:.17g}\n{}_s = {:.17g}\n", name, window->start_s, name, window->duration_s);
  }
  out += fmt::format("thruster_failure_t_s = {:.17g}\nclock_jump_t_s = {:.17g}\nclock_jump_m = {:.17g}\n\n",
                     s.fault.thruster_failure_t_s, s.fault.clock_jump_t_s, s.fault.clock_jump_m);
  out += gnss_settings_to_toml(s.gnss);
  out += s.forces_toml;
  out += s.nav_toml;
  return out;
}

}  // namespace visors::sim
