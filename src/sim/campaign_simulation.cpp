#include "sim/campaign_simulation.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "astro/mean_osculating.hpp"
#include "astro/relative_orbital_elements.hpp"
#include "astro/sun_moon.hpp"
#include "core/rtn_frame.hpp"
#include "dynamics/force_model.hpp"
#include "dynamics/orbit_propagator.hpp"
#include "gnc/flight_component.hpp"
#include "sim/alignment_metrics.hpp"
#include "sim/attitude_profile.hpp"
#include "sim/crosslink.hpp"
#include "sim/drag_area.hpp"
#include "sim/formation_initial_state.hpp"
#include "sim/truth_dynamics.hpp"
#include "sim/ideal_navigation.hpp"
#include "sim/propulsion.hpp"
#include "sim/run_recorder.hpp"
#include "sim/spacecraft_geometry.hpp"

namespace visors::sim {

namespace {

using gnc::Mode;
using gnc::Spacecraft;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// The host switches roles after the active spacecraft has reported GNC incapable this long [s].
constexpr double kRoleSwitchAfter = 60.0;

struct Vehicle {
  Spacecraft id = Spacecraft::dsc;
  std::string_view name;
  TruthDynamics truth;  // force model and propagator
  core::StateVector x_gcrf;
  std::optional<Propulsion> propulsion;
  std::optional<AttitudeProfile> attitude;
  DragArea drag = DragArea::visors_6u();
  std::optional<SpacecraftGeometry> geometry;
  std::optional<gnc::FlightComponent> gnc;
  std::optional<IdealNavigation> navigation;
  std::optional<Crosslink<gnc::CrosslinkMessage>> inbox;  // messages from the other spacecraft
  Eigen::Quaterniond q_body_to_gcrf = Eigen::Quaterniond::Identity();
  std::array<double, gnc::kModeCount> dv_by_mode{};  // executed, L1 in the thrusters' frame [m/s]
  double dv_total = 0.0;
  std::optional<gnc::PropulsionTelemetry> telemetry;  // delivered at the next step
  std::optional<gnc::GroundCommand> command;          // delivered at the next step
  gnc::GncOutputs out;
  bool violation_reported = false;
  double incapable_since = -1.0;
};

struct PendingObservation {
  AlignmentResult result;
  double start_s = 0.0, end_s = 0.0;
  bool done = false;
};

core::Result<bool> set_up_vehicle(Vehicle& v, const CampaignScenario& s, const SpacecraftSettings& sc, bool active,
                                  const core::StateVector& x0) {
  const std::string prefix(v.name);
  auto dynamics = make_truth_dynamics(s, sc, prefix);
  if (!dynamics.ok()) return dynamics.error();
  v.truth = std::move(dynamics).value();
  v.x_gcrf = x0;
  auto propulsion = Propulsion::create(s.propulsion, sc.mass_kg, sc.propellant_kg, RandomStream(s.seed, prefix + ".propulsion"));
  if (!propulsion.ok()) return core::Error{prefix + "." + propulsion.error().field, propulsion.error().message};
  v.propulsion.emplace(std::move(propulsion).value());
  AttitudeSettings attitude_settings;
  attitude_settings.slew_rate_radps = s.gnc.science.slew_rate_rad_s;
  attitude_settings.settling_s = s.gnc.science.slew_settle_s;
  auto attitude = AttitudeProfile::create(attitude_settings);
  if (!attitude.ok()) return core::Error{"gnc.science." + attitude.error().field, attitude.error().message};
  v.attitude.emplace(std::move(attitude).value());
  RandomStream geometry_rng(s.seed, prefix + ".geometry");
  GeometrySettings geometry_settings;
  v.geometry.emplace(SpacecraftGeometry::draw(geometry_settings, geometry_rng));
  gnc::GncConfig config = s.gnc;
  config.self = v.id;
  config.active = active;
  config.mass_kg = sc.mass_kg;
  auto component = gnc::FlightComponent::create(config);
  if (!component.ok()) return core::Error{"gnc." + component.error().field, component.error().message};
  v.gnc.emplace(std::move(component).value());
  v.navigation.emplace(s.navigation, RandomStream(s.seed, prefix + ".navigation"));
  CrosslinkSettings link;
  link.delay_s = s.crosslink_delay_s;
  link.drop_probability = s.crosslink_drop_probability;
  auto inbox = Crosslink<gnc::CrosslinkMessage>::create(link, RandomStream(s.seed, prefix + ".crosslink"));
  if (!inbox.ok()) return core::Error{"crosslink." + inbox.error().field, inbox.error().message};
  v.inbox.emplace(std::move(inbox).value());
  return true;
}

// Truth relative geometry (every step: the minimum separations): RTN position and inertial
// velocity difference in RTN axes, RN and 3D separations.
TimeseriesRow truth_geometry(const core::StateVector& dsc, const core::StateVector& osc) {
  TimeseriesRow row;
  const Eigen::Matrix3d to_rtn = core::gcrf_to_rtn_matrix(dsc);
  row.r_rtn_m = to_rtn * (osc.r - dsc.r);
  row.v_rtn_mps = to_rtn * (osc.v - dsc.v);
  row.sep_3d_m = row.r_rtn_m.norm();
  row.sep_rn_m = std::hypot(row.r_rtn_m(0), row.r_rtn_m(2));
  return row;
}

// Truth ROE for the time series (output steps only: the mean elements are iterated): osculating,
// and mean through the first-order J2 mean elements of both spacecraft.
void add_truth_roe(const core::StateVector& dsc, const core::StateVector& osc, const core::EarthGravityConstants& g,
                   TimeseriesRow& row) {
  const auto kc = astro::cartesian_to_keplerian(dsc.r, dsc.v, g.mu);
  const auto kd = astro::cartesian_to_keplerian(osc.r, osc.v, g.mu);
  if (!kc.ok() || !kd.ok()) return;
  if (const auto roe = astro::roe_from_keplerian(*kc, *kd); roe.ok()) row.roe_osc_m = kc->a * *roe;
  const auto mc = astro::mean_from_osculating(*kc, g);
  const auto md = astro::mean_from_osculating(*kd, g);
  if (!mc.ok() || !md.ok()) return;
  if (const auto roe = astro::roe_from_keplerian(*mc, *md); roe.ok()) row.roe_mean_m = mc->a * *roe;
}

std::string vector_text(const Eigen::Vector3d& x, double scale) {
  return fmt::format("[{:.4f}, {:.4f}, {:.4f}]", scale * x(0), scale * x(1), scale * x(2));
}

}  // namespace

core::Result<RunResult> run_campaign(const CampaignScenario& s, const std::filesystem::path& out_dir,
                                     const std::function<void(const RunProgress&)>& progress) {
  const auto wall_start = std::chrono::steady_clock::now();
  const core::EarthGravityConstants& g = s.gnc.gravity;
  auto recorder_result = RunRecorder::open(out_dir, campaign_to_toml(s));
  if (!recorder_result.ok()) return recorder_result.error();
  RunRecorder recorder = std::move(recorder_result).value();

  // ---- Initial states: chief mean elements, deputy from the initial mean ROE.
  const auto initial = initial_formation_state(s);
  if (!initial.ok()) return initial.error();

  std::array<Vehicle, 2> vehicles;
  Vehicle& dsc = vehicles[0];
  Vehicle& osc = vehicles[1];
  dsc.id = Spacecraft::dsc;
  dsc.name = "dsc";
  osc.id = Spacecraft::osc;
  osc.name = "osc";
  if (auto ok = set_up_vehicle(dsc, s, s.dsc, s.active == "dsc", initial->dsc_gcrf); !ok) return ok.error();
  if (auto ok = set_up_vehicle(osc, s, s.osc, s.active == "osc", initial->osc_gcrf); !ok) return ok.error();
  for (Vehicle& v : vehicles) {
    for (const auto& warning : v.truth.forces->warnings()) recorder.event(0.0, v.name, "warning", warning);
  }

  const AlignmentRequirements requirements;
  std::vector<PendingObservation> observations;
  observations.reserve(static_cast<std::size_t>(s.observations) + 4);
  double min_sep_rn = std::numeric_limits<double>::infinity();
  double min_sep_3d = std::numeric_limits<double>::infinity();
  int safety_violations = 0;
  bool science_started = false, left_science = false, escaped = false;
  double end_s = s.observations == 0 ? s.standby_s + s.tail_s : s.max_duration_s;
  const auto steps_total = static_cast<std::int64_t>(std::floor(s.max_duration_s / s.step_s + 1e-9));
  const auto output_every = static_cast<std::int64_t>(std::llround(s.output_step_s / s.step_s));
  const auto science_step = static_cast<std::int64_t>(std::llround(s.standby_s / s.step_s));
  const auto fault_step = s.fault.impulse_t_s >= 0.0 ? static_cast<std::int64_t>(std::llround(s.fault.impulse_t_s / s.step_s)) : -1;
  const auto non_gnc_fault_step =
      s.fault.non_gnc_fault_t_s >= 0.0 ? static_cast<std::int64_t>(std::llround(s.fault.non_gnc_fault_t_s / s.step_s)) : -1;
  double ts = 0.0;

  for (std::int64_t k = 0; k <= steps_total; ++k) {
    ts = static_cast<double>(k) * s.step_s;
    if (ts > end_s) break;
    const core::GpsTime t = s.t0 + ts;
    const Eigen::Vector3d sun_gcrf = astro::sun_position_gcrf(t);

    // ---- Attitude and drag area.
    for (Vehicle& v : vehicles) {
      const Eigen::Vector3d sun_unit = (sun_gcrf - v.x_gcrf.r).normalized();
      v.q_body_to_gcrf = v.attitude->body_to_gcrf(ts, v.x_gcrf.r, v.x_gcrf.v, sun_unit);
      v.truth.forces->set_drag_area(v.drag.projected_area_m2(air_velocity_body_unit(v.x_gcrf, v.q_body_to_gcrf)));
    }

    // ---- Ground timeline.
    if (k == 0) {
      for (Vehicle& v : vehicles) v.command = gnc::GroundCommand{t, gnc::GroundCommand::Kind::to_standby, 0};
    }
    if (k == science_step && s.observations > 0) {
      for (Vehicle& v : vehicles) v.command = gnc::GroundCommand{t, gnc::GroundCommand::Kind::start_science, s.observations};
      science_started = true;
      recorder.event(ts, "sim", "command", fmt::format("start_science, {} observations", s.observations));
    }

    // ---- One step of each flight component.
    for (Vehicle& v : vehicles) {
      gnc::GncInputs in;
      in.t = t;
      in.time_at_tone = gnc::TimeAtTone{t, v.q_body_to_gcrf};
      in.navigation = v.navigation->solve(t, dsc.x_gcrf, osc.x_gcrf, k == 0 ? 0.0 : s.step_s);
      auto delivered = v.inbox->receive(ts);
      if (!delivered.empty()) in.crosslink = delivered.back();  // the newest state of the other spacecraft
      in.command = v.command;
      in.propulsion = v.telemetry;
      v.command.reset();
      v.telemetry.reset();
      const Mode before = v.gnc->mode();
      v.out = v.gnc->step(in);
      if (v.out.mode != before) recorder.event(ts, v.name, "mode", fmt::format("{} -> {}", to_string(before), to_string(v.out.mode)));
    }

    // ---- Host application: routing, actuators, FDIR.
    for (std::size_t i = 0; i < 2; ++i) {
      Vehicle& v = vehicles[i];
      Vehicle& other = vehicles[1 - i];
      if (v.out.crosslink) other.inbox->send(ts, *v.out.crosslink);
      if (v.out.observation) {
        const auto& o = *v.out.observation;
        const ObservationWindow window{o.slew_start.seconds_since(s.t0), o.start.seconds_since(s.t0), o.end.seconds_since(s.t0)};
        if (auto ok = v.attitude->schedule(window); !ok) recorder.event(ts, v.name, "rejected_message", ok.error().describe());
        if (v.out.telemetry.active) {
          PendingObservation p;
          p.result.index = o.index;
          p.result.t_s = window.start_s;
          p.start_s = window.start_s;
          p.end_s = window.end_s;
          observations.push_back(p);
          const auto& target = v.out.telemetry.roe_target_m;
          recorder.event(ts, v.name, "observation",
                         fmt::format("attempt {} scheduled at t = {:.1f} s, target a*roe = [{:.3f}, {:.3f}, {:.3f}, {:.3f}, {:.3f}, {:.3f}] m",
                                     o.index, window.start_s, target(0), target(1), target(2), target(3), target(4), target(5)));
        }
      }
      if (v.out.maneuver) {
        const Mode mode = v.out.mode;
        auto executed = v.propulsion->execute(ts, v.out.maneuver->dv_body_mps);
        gnc::PropulsionTelemetry telemetry;
        telemetry.t = t;
        telemetry.mass_kg = v.propulsion->mass_kg();
        if (executed.ok()) {
          v.x_gcrf.v += v.q_body_to_gcrf * executed->dv_executed_body_mps;
          const double l1 = thruster_l1_norm(executed->dv_executed_body_mps);
          v.dv_by_mode[static_cast<std::size_t>(mode)] += l1;
          v.dv_total += l1;
          telemetry.dv_body_mps = executed->dv_commanded_body_mps;
          telemetry.executed = true;
          recorder.event(ts, v.name, "maneuver",
                         fmt::format("{} dv_rtn = {} mm/s, executed |dv| = {:.4f} mm/s", to_string(mode),
                                     vector_text(v.out.maneuver->dv_rtn_mps, 1e3), 1e3 * executed->dv_executed_body_mps.norm()));
        } else {
          recorder.event(ts, v.name, "maneuver", "refused by propulsion: " + executed.error().describe());
        }
        v.telemetry = telemetry;
      }
      // FDIR responses of the host application.
      if (v.out.telemetry.active) {
        if (v.out.passive_safety_violated && !v.violation_reported) {
          v.violation_reported = true;
          ++safety_violations;
          v.command = gnc::GroundCommand{t + s.step_s, gnc::GroundCommand::Kind::escape, 0};
          recorder.event(ts, v.name, "safety_violation",
                         fmt::format("passive-safety margin {:.3f} m below epsilon; host commands escape", v.out.telemetry.safety_margin_m));
        }
        if (!v.out.passive_safety_violated) v.violation_reported = false;
        if (v.out.gnc_incapable) {
          if (v.incapable_since < 0.0) v.incapable_since = ts;
          if (ts - v.incapable_since >= kRoleSwitchAfter && !other.out.gnc_incapable) {
            v.command = gnc::GroundCommand{t + s.step_s, gnc::GroundCommand::Kind::make_passive, 0};
            other.command = gnc::GroundCommand{t + s.step_s, gnc::GroundCommand::Kind::make_active, 0};
            v.incapable_since = -1.0;
            recorder.event(ts, "sim", "fdir", fmt::format("{} GNC incapable: role switch", v.name));
          }
        } else {
          v.incapable_since = -1.0;
        }
      }
    }
    if (k == non_gnc_fault_step) {
      // Host FDIR for a non-GNC fault (mission paper): back to standby from science or transfer,
      // else a role switch.
      Vehicle& active_now = dsc.out.telemetry.active ? dsc : osc;
      Vehicle& passive_now = dsc.out.telemetry.active ? osc : dsc;
      const Mode mode_now = active_now.out.mode;
      if (mode_now == Mode::science || mode_now == Mode::transfer_to_science) {
        active_now.command = gnc::GroundCommand{t + s.step_s, gnc::GroundCommand::Kind::transfer_to_standby, 0};
        recorder.event(ts, "sim", "fdir", "non-GNC fault: transfer to standby");
      } else {
        active_now.command = gnc::GroundCommand{t + s.step_s, gnc::GroundCommand::Kind::make_passive, 0};
        passive_now.command = gnc::GroundCommand{t + s.step_s, gnc::GroundCommand::Kind::make_active, 0};
        recorder.event(ts, "sim", "fdir", "non-GNC fault: role switch");
      }
    }
    if (k == fault_step) {
      const Eigen::Matrix3d rtn_to_gcrf = core::gcrf_to_rtn_matrix(osc.x_gcrf).transpose();
      osc.x_gcrf.v += rtn_to_gcrf * s.fault.impulse_dv_rtn_mps;
      recorder.event(ts, "osc", "fault", "unplanned impulse dv_rtn = " + vector_text(s.fault.impulse_dv_rtn_mps, 1e3) + " mm/s");
    }

    // ---- Metrics.
    const Vehicle& active = dsc.out.telemetry.active ? dsc : osc;
    for (PendingObservation& p : observations) {
      if (p.done) continue;
      if (ts >= p.start_s && ts <= p.end_s) {
        const Eigen::Vector3d p_osc = osc.x_gcrf.r + osc.q_body_to_gcrf * osc.geometry->payload_from_com_body_m();
        const Eigen::Vector3d p_dsc = dsc.x_gcrf.r + dsc.q_body_to_gcrf * dsc.geometry->payload_from_com_body_m();
        add_alignment_sample(p.result, p_osc, osc.x_gcrf.v, p_dsc, dsc.x_gcrf.v, (sun_gcrf - dsc.x_gcrf.r).normalized(),
                             requirements);
      } else if (ts > p.end_s) {
        p.done = true;
        const bool ok = p.result.success(requirements);
        recorder.observation(p.result, ok);
        recorder.event(ts, "sim", "observation",
                       fmt::format("attempt {}: lateral {:.2f} mm, lateral velocity {:.3f} mm/s, focus {:.2f} mm: {}", p.result.index,
                                   1e3 * p.result.lateral_error_m, 1e3 * p.result.lateral_velocity_mps,
                                   1e3 * p.result.focus_error_m, ok ? "success" : "failure"));
      }
    }
    TimeseriesRow row = truth_geometry(dsc.x_gcrf, osc.x_gcrf);
    min_sep_rn = std::min(min_sep_rn, row.sep_rn_m);
    min_sep_3d = std::min(min_sep_3d, row.sep_3d_m);
    if (k % output_every == 0) {
      add_truth_roe(dsc.x_gcrf, osc.x_gcrf, g, row);
      row.t_s = ts;
      row.mode = to_string(active.out.mode);
      row.active = active.name;
      row.has_margin = active.out.telemetry.safety_checked;
      row.safety_margin_m = active.out.telemetry.safety_margin_m;
      row.dv_dsc_mps = dsc.dv_total;
      row.dv_osc_mps = osc.dv_total;
      recorder.timeseries(row);
    }

    // ---- End of the campaign.
    const Mode mode = active.out.mode;
    if (science_started && (mode == Mode::transfer_to_standby || mode == Mode::science)) left_science = true;
    if (!escaped && mode == Mode::escape) escaped = true;
    if (end_s >= s.max_duration_s && ((left_science && mode == Mode::standby) || (escaped && mode == Mode::manual))) {
      end_s = ts + s.tail_s;
    }
    if (progress && k % 60 == 0) {
      progress(RunProgress{ts, end_s, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count()});
    }

    // ---- Truth propagation to the next step.
    for (Vehicle& v : vehicles) {
      auto next = v.truth.propagator->propagate_to(t, v.x_gcrf, t + s.step_s);
      if (!next.ok()) return core::Error{std::string(v.name) + " truth", next.error().describe()};
      v.x_gcrf = *next;
    }
  }

  // ---- Summary.
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  nlohmann::json summary;
  summary["scenario"] = s.name;
  summary["seed"] = s.seed;
  summary["t0"] = {{"iso", s.t0.format(core::TimeScale::kGps, 3)}, {"week", s.t0.week()}, {"seconds_of_week", s.t0.seconds_of_week()}};
  summary["simulated_s"] = ts;
  summary["wall_s"] = wall;
  nlohmann::json list = nlohmann::json::array();
  int successes = 0, attempts = 0;
  for (const PendingObservation& p : observations) {
    if (!p.done) continue;
    const bool ok = p.result.success(requirements);
    successes += ok ? 1 : 0;
    ++attempts;
    list.push_back({{"index", p.result.index}, {"t_gps", p.result.t_s}, {"lateral_error_m", p.result.lateral_error_m},
                    {"lateral_velocity_mps", p.result.lateral_velocity_mps}, {"focus_error_m", p.result.focus_error_m},
                    {"success", ok}});
  }
  summary["observations"] = list;
  summary["success_rate"] = attempts > 0 ? static_cast<double>(successes) / attempts : 0.0;
  summary["requirements"] = {{"lateral_error_m", requirements.lateral_error_m},
                             {"lateral_velocity_mps", requirements.lateral_velocity_mps},
                             {"focus_error_m", requirements.focus_error_m},
                             {"safety_epsilon_m", s.gnc.safety.epsilon}};
  nlohmann::json dv;
  for (const Vehicle& v : vehicles) {
    nlohmann::json by_mode;
    for (int m = 0; m < gnc::kModeCount; ++m) by_mode[std::string(to_string(static_cast<Mode>(m)))] = v.dv_by_mode[static_cast<std::size_t>(m)];
    by_mode["total"] = v.dv_total;
    dv[std::string(v.name)] = by_mode;
  }
  summary["delta_v_mps"] = dv;
  summary["paper_budget_mps"] = {{"standby_per_week", 0.3488}, {"transfer_to_science", 0.4934},
                                 {"transfer_to_standby", 0.4844}, {"science_per_observation", 0.0048}};
  summary["min_separation_rn_m"] = min_sep_rn;
  summary["min_separation_3d_m"] = min_sep_3d;
  summary["safety_violations"] = safety_violations;
  const Vehicle& active = dsc.out.telemetry.active ? dsc : osc;
  summary["final_mode"] = to_string(active.out.mode);
  summary["rejected_inputs"] = dsc.out.telemetry.rejected.total() + osc.out.telemetry.rejected.total();
  summary["planning_failures"] = dsc.out.telemetry.planning_failures + osc.out.telemetry.planning_failures;
  if (auto ok = recorder.finish(summary); !ok) return ok.error();
  return RunResult{summary, out_dir};
}

}  // namespace visors::sim
