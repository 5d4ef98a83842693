#include "visors/sim/campaign_simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "visors/core/files/data_path.hpp"
#include "visors/report/run_directory.hpp"
#include "visors/sim/data_provenance.hpp"
#include "visors/sim/flight_config.hpp"
#include "visors/sim/formation_initial_state.hpp"

namespace visors::sim {

namespace {

using gnc::Mode;
using gnc::Spacecraft;

constexpr int kSolutionSatellites = 4;  // a receiver's position and time solution needs four

std::string vector_text(const Eigen::Vector3d& x, double scale) {
  return fmt::format("[{:.4f}, {:.4f}, {:.4f}]", scale * x(0), scale * x(1), scale * x(2));
}

// The GPS world of a cdgps run, or nothing: without the constellation there is no GPS to navigate
// with, and the run goes on with ideal navigation (the main command works without the shared
// data), loudly (`fallbacks`, the event log).
core::Result<std::optional<GpsWorld>> load_gps(CampaignScenario& s, RunRecorder& recorder, std::vector<std::string>& fallbacks) {
  if (s.navigation_mode != NavigationMode::kCdgps) return std::optional<GpsWorld>{};
  if (!core::files::find_data_file(s.gnss.nav_file)) {
    s.navigation_mode = NavigationMode::kIdeal;
    fallbacks.push_back(fmt::format("gnss.nav_file '{}' not found in the data search path: no GPS constellation, "
                                    "so navigation mode cdgps falls back to ideal navigation (the [navigation] errors)",
                                    s.gnss.nav_file));
    recorder.event(0.0, "sim", "warning", fallbacks.back());
    return std::optional<GpsWorld>{};
  }
  auto world = load_gps_world(s, s.max_duration_s);
  if (!world.ok()) return world.error();
  if (auto ok = recorder.open_navigation(); !ok) return ok.error();
  return std::optional<GpsWorld>(std::move(world).value());
}

// What the truth drew for each spacecraft (the event log) and the truth models' warnings.
void record_truth_draws(const CampaignScenario& s, const TruthWorld& truth, RunRecorder& recorder,
                        std::vector<std::string>& fallbacks) {
  for (const TruthSpacecraft& x : truth.craft()) {
    const SpacecraftSettings& t = x.true_spacecraft;
    const double told_kg = x.id == Spacecraft::kDsc ? s.flight.dsc_mass_kg : s.flight.osc_mass_kg;
    recorder.event(0.0, x.name, "truth",
                   fmt::format("mass {:.4f} kg, Cd {:.4f}, Cr {:.4f} (the flight software is told {:.4f} kg, {:.4f}, {:.4f})",
                               t.mass_kg, t.cd, t.cr, told_kg, s.flight.cd, s.flight.cr));
    for (const auto& warning : x.dynamics.forces->warnings()) {
      recorder.event(0.0, x.name, "warning", warning);
      if (std::find(fallbacks.begin(), fallbacks.end(), warning) == fallbacks.end()) fallbacks.push_back(warning);
    }
  }
}

// One component's refused inputs (gnc/input_rejections.hpp): every reason and every channel by
// name, zeros included, so that a summary always has the same keys.
nlohmann::json rejections_json(const gnc::InputRejections& rejected) {
  nlohmann::json out;
  for (int r = 1; r < gnc::kRejectionReasons; ++r) {
    const auto reason = static_cast<gnc::RejectionReason>(r);
    out["by_reason"][std::string(gnc::to_string(reason))] = rejected.of(reason);
  }
  out["by_channel"]["unknown"] = rejected.by_channel[0];
  for (int c = 1; c <= gnc::kChannels; ++c) {
    const auto channel = static_cast<gnc::Channel>(c);
    out["by_channel"][std::string(gnc::to_string(channel))] = rejected.of(channel);
  }
  return out;
}

}  // namespace

CampaignSimulation::CampaignSimulation(const CampaignScenario& scenario, RunRecorder& recorder, TruthWorld truth,
                                       Sensors sensors, HostApplication host)
    : scenario_(scenario),
      recorder_(&recorder),
      truth_(std::move(truth)),
      sensors_(std::move(sensors)),
      host_(std::move(host)),
      metrics_(recorder, scenario.observations, scenario.step_s) {
  const CampaignScenario& s = scenario_;
  end_s_ = s.observations == 0 ? s.standby_s + s.tail_s : s.max_duration_s;
  steps_total_ = static_cast<std::int64_t>(std::floor(s.max_duration_s / s.step_s + 1e-9));
  output_every_ = static_cast<std::int64_t>(std::llround(s.output_step_s / s.step_s));
  fault_step_ = step_at(s.fault.impulse_t_s, s.step_s);
  non_gnc_fault_step_ = step_at(s.fault.non_gnc_fault_t_s, s.step_s);
  metrics_.set_aim(s.t0, s.gnc.science.geometry);
}

core::Result<CampaignSimulation> CampaignSimulation::create(const CampaignScenario& scenario, RunRecorder& recorder,
                                                           const RunOptions& options) {
  // Initial states: chief mean elements, deputy from the initial mean ROE.
  const auto initial = initial_formation_state(scenario);
  if (!initial.ok()) return initial.error();
  CampaignScenario s = scenario;
  std::vector<std::string> fallbacks;
  auto gps = load_gps(s, recorder, fallbacks);
  if (!gps.ok()) return gps.error();
  // What the flight components are created with (the functions HostApplication uses).
  auto config = flight_config_json(s);
  if (!config.ok()) return config.error();
  if (auto ok = recorder.flight_config(config.value()); !ok) return ok.error();
  auto truth = TruthWorld::create(s, initial->dsc_gcrf, initial->osc_gcrf);
  if (!truth.ok()) return truth.error();
  const bool with_gps = gps.value().has_value();
  auto sensors = Sensors::create(s, truth.value(), std::move(gps).value());
  if (!sensors.ok()) return sensors.error();
  auto software = FlightSoftware::create(config.value(), recorder.dir() / std::string(report::kFlightConfigFile), recorder.dir(),
                                         FlightSoftwareOptions{.parallel_components = options.parallel_components,
                                                               .process_command = options.fsw_command});
  if (!software.ok()) return software.error();
  auto host = HostApplication::create(s, recorder, with_gps, std::move(software).value());
  if (!host.ok()) return host.error();
  record_truth_draws(s, truth.value(), recorder, fallbacks);
  CampaignSimulation sim(s, recorder, std::move(truth).value(), std::move(sensors).value(), std::move(host).value());
  sim.fallbacks_ = std::move(fallbacks);
  return sim;
}

core::Result<bool> CampaignSimulation::step() {
  if (ended_) return false;
  if (k_ > steps_total_) {
    ended_ = true;
    return false;
  }
  const double ts = static_cast<double>(k_) * scenario_.step_s;
  ts_ = ts;
  if (ts > end_s_) {
    ended_ = true;
    return false;
  }
  const core::GpsTime t = scenario_.t0 + ts;
  truth_.update_attitude(t, ts_);
  host_.apply_ground_timeline(k_, t, ts_);
  if (auto ok = step_flight_components(t); !ok) return ok.error();
  if (sensors_.has_gps()) metrics_.score_navigation(truth_, sensors_, host_, scenario_.flight, ts_, in_slew(ts_));
  // Per spacecraft, in order: the host routes its outputs, then applies its FDIR (the event log
  // keeps this order).
  for (std::size_t k = 0; k < 2; ++k) {
    route_outputs(k);
    host_.apply_fdir(k, t, ts_);
  }
  inject_faults(t);
  const bool navigation_rows = sensors_.has_gps() && k_ % output_every_ == 0;
  metrics_.record(truth_, host_, t, ts_, k_, output_every_, scenario_.gnc.gravity, sensors_.has_gps(),
                  navigation_rows && in_slew(ts_), navigation_rows && in_observation(ts_));
  update_end();
  if (auto ok = truth_.propagate(t, scenario_.step_s); !ok) return ok.error();
  ++k_;
  return true;
}

// The fault windows, then each component's input records (sensors, crosslink, commands: in order,
// since the sensors share the simulator's state: the constellation's caches, the scores, the
// events) and one step of both components side by side.
core::Result<bool> CampaignSimulation::step_flight_components(core::GpsTime t) {
  const EpochFrame frame = sensors_.frame(t);
  if (const auto jump = host_.open_fault_windows(k_, t, ts_)) sensors_.receiver(*jump).jump_clock(scenario_.fault.clock_jump_m);
  host_.close_fault_windows(t, ts_);
  std::array<bool, 2> stepped{};
  for (std::size_t k = 0; k < 2; ++k) {
    HostedComponent& c = host_[k];
    HostRecords& records = host_records_[k];
    records.clear();
    if (host_.in_safe_mode(k, ts_)) {
      // Bus safe mode: the component is not stepped; nothing comes out of it.
      c.out.maneuver.reset();
      c.out.observation.reset();
      c.crosslink_out.size = 0;
      continue;
    }
    stepped[k] = true;
    measure(k, frame, t, records);
    for (const auto& delivered : c.inbox->receive(ts_)) records.forward(delivered);
    if (c.command) records.add(c.sequence, *c.command);
    if (c.telemetry) records.add(c.sequence, *c.telemetry);
    host_.add_garbage(k, t, ts_, records);
    c.command = c.command_after;
    c.command_after.reset();
    c.telemetry.reset();
  }
  return host_.step_components(t, ts_, stepped, host_records_, metrics_.step_us());
}

// Spacecraft k's sensor messages of this step: the time at tone with the attitude its ADCS
// reports, the GPS message (or the ideal navigation's solution), the OSC's laser range; then the
// tone's true instant, disciplined by the receiver's solution when it has one.
void CampaignSimulation::measure(std::size_t k, const EpochFrame& frame, core::GpsTime t, HostRecords& records) {
  const TruthSpacecraft& x = truth_[k];
  HostedComponent& c = host_[k];
  records.add(c.sequence, gnc::TimeAtTone{t, x.q_reported_body_to_gcrf});
  bool solution = !sensors_.has_gps();  // ideal navigation: the receiver is not simulated, its PPS is
  if (sensors_.has_gps()) {
    if (host_.in_gps_outage(k, ts_)) {
      sensors_.receiver(k).reacquire_all();  // the receiver restarts when the outage ends
    } else if (const auto gps = sensors_.measure_gps(k, x, frame, t, ts_, metrics_.navigation_score())) {
      records.add(c.sequence, *gps);
      solution = gps->epoch.channel_count >= kSolutionSatellites;
    }
    if (x.id == Spacecraft::kOsc) {
      if (const auto range = sensors_.measure_range(truth_, t, ts_, k_, c.out.lrf_power)) records.add(c.sequence, *range);
    }
  } else {
    records.add(c.sequence, sensors_.ideal_solution(k, t, truth_, k_ == 0 ? 0.0 : scenario_.step_s));
  }
  sensors_.tone(k, ts_, solution);
}

// Where the observations are (the active spacecraft's schedule, which the passive one follows):
// in a window, or in the slew to it or back from it (as long as the slew to it).
bool CampaignSimulation::in_observation(double t_s) const {
  for (const ObservationWindow& w : truth_[host_.active_index()].attitude->windows()) {
    if (t_s >= w.start_s && t_s <= w.end_s) return true;
  }
  return false;
}

bool CampaignSimulation::in_slew(double t_s) const {
  for (const ObservationWindow& w : truth_[host_.active_index()].attitude->windows()) {
    const double lead = w.start_s - w.slew_start_s;
    if ((t_s >= w.slew_start_s && t_s < w.start_s) || (t_s > w.end_s && t_s <= w.end_s + lead)) return true;
  }
  return false;
}

// Host routing: crosslink to the other spacecraft, observation schedule to the truth attitude
// (and, from the active spacecraft, to the metrics), maneuvers to the truth propulsion.
void CampaignSimulation::route_outputs(std::size_t k) {
  HostedComponent& v = host_[k];
  if (v.crosslink_out.size > 0 && !host_.crosslink_lost(ts_)) host_[1 - k].inbox->send(ts_, v.crosslink_out);
  if (v.out.observation) {
    const auto& o = *v.out.observation;
    const core::GpsTime t0 = scenario_.t0;
    const ObservationWindow window{o.slew_start.seconds_since(t0), o.start.seconds_since(t0), o.end.seconds_since(t0)};
    if (auto ok = truth_[k].attitude->schedule(window); !ok) recorder_->event(ts_, v.name, "rejected_message", ok.error().describe());
    if (v.out.telemetry.active) {
      metrics_.open_observation(o.index, window.start_s, window.end_s);
      const auto& target = v.out.telemetry.roe_target_m;
      recorder_->event(ts_, v.name, "observation",
                       fmt::format("attempt {} scheduled at t = {:.1f} s, target a*roe = [{:.3f}, {:.3f}, {:.3f}, {:.3f}, {:.3f}, {:.3f}] m",
                                   o.index, window.start_s, target(0), target(1), target(2), target(3), target(4), target(5)));
    }
  }
  if (v.out.maneuver) execute_maneuver(k, scenario_.t0 + ts_);
}

// The truth propulsion executes the commanded impulse (with its errors) at the tone's true
// instant; its telemetry goes back at the next step. A failed thruster executes nothing, its
// telemetry says so, and the host's FDIR responds (once, while it is active).
void CampaignSimulation::execute_maneuver(std::size_t k, core::GpsTime t) {
  HostedComponent& v = host_[k];
  const Mode mode = v.out.mode;
  gnc::PropulsionTelemetry telemetry;
  telemetry.t = t;
  telemetry.mass_kg = truth_[k].propulsion->mass_kg();
  if (host_.thruster_failed(k)) {
    v.telemetry = telemetry;
    if (v.out.telemetry.active) {
      host_.respond(FdirTrigger::kUnableToAct, k, t + scenario_.step_s, ts_, fmt::format("{} thruster failed", v.name));
    }
    return;
  }
  // Intended: the commanded body impulse through the attitude the flight software was told.
  const Eigen::Vector3d intended_gcrf = truth_[k].q_reported_body_to_gcrf * v.out.maneuver->dv_body_mps;
  auto executed = truth_.execute_impulse(k, ts_, v.out.maneuver->dv_body_mps, sensors_.clock(k).offset_s());
  if (executed.ok()) {
    metrics_.add_impulse_error(k, ts_, truth_[k].q_body_to_gcrf * executed->dv_executed_body_mps - intended_gcrf, truth_[0].x_gcrf);
    metrics_.add_delta_v(k, mode, thruster_l1_norm(executed->dv_executed_body_mps));
    telemetry.dv_body_mps = executed->dv_commanded_body_mps;
    telemetry.executed = true;
    recorder_->event(ts_, v.name, "maneuver",
                     fmt::format("{} dv_rtn = {} mm/s, executed |dv| = {:.4f} mm/s", to_string(mode),
                                 vector_text(v.out.maneuver->dv_rtn_mps, 1e3), 1e3 * executed->dv_executed_body_mps.norm()));
  } else {
    recorder_->event(ts_, v.name, "maneuver", "refused by propulsion: " + executed.error().describe());
  }
  v.telemetry = telemetry;
}

// Scenario faults: a non-GNC fault reported to the host (its FDIR policy), and an unplanned
// impulse on the OSC's truth.
void CampaignSimulation::inject_faults(core::GpsTime t) {
  if (k_ == non_gnc_fault_step_) {
    host_.respond(FdirTrigger::kNonGncFault, host_.active_index(), t + scenario_.step_s, ts_, "non-GNC fault");
  }
  if (k_ == fault_step_) {
    truth_.apply_impulse_rtn(1, scenario_.fault.impulse_dv_rtn_mps);
    recorder_->event(ts_, "osc", "fault", "unplanned impulse dv_rtn = " + vector_text(scenario_.fault.impulse_dv_rtn_mps, 1e3) + " mm/s");
  }
}

// The campaign ends tail_s after the active spacecraft is back in standby after science, or in
// manual after an escape.
void CampaignSimulation::update_end() {
  const Mode mode = host_[host_.active_index()].out.mode;
  if (host_.science_started() && (mode == Mode::kTransferToStandby || mode == Mode::kScience)) left_science_ = true;
  if (!escaped_ && mode == Mode::kEscape) escaped_ = true;
  if (end_s_ >= scenario_.max_duration_s && ((left_science_ && mode == Mode::kStandby) || (escaped_ && mode == Mode::kManual))) {
    end_s_ = ts_ + scenario_.tail_s;
  }
}

// What the run drew (docs/run-directory.md "truth"): the truth world's draws, each computer's
// oscillator and largest tone offset, each receiver's true phase centre.
nlohmann::json CampaignSimulation::truth_summary() const {
  nlohmann::json out = truth_.summary();
  for (std::size_t k = 0; k < 2; ++k) {
    nlohmann::json& t = out[std::string(truth_[k].name)];
    t["clock_frequency_error"] = sensors_.clock(k).frequency_error();
    t["clock_max_abs_offset_s"] = sensors_.clock(k).max_abs_offset_s();
    if (sensors_.has_gps()) {
      const Eigen::Vector3d p = sensors_.receiver(k).phase_center_body_m();
      t["phase_center_body_m"] = nlohmann::json::array({p.x(), p.y(), p.z()});
    }
  }
  return out;
}

nlohmann::json CampaignSimulation::summary(double wall_s) const {
  const CampaignScenario& s = scenario_;
  nlohmann::json summary;
  summary["format_version"] = kRunDirectoryFormatVersion;
  summary["scenario"] = s.name;
  summary["seed"] = s.seed;
  summary["t0"] = {{"iso", s.t0.format(core::TimeScale::kGps, 3)}, {"week", s.t0.week()}, {"seconds_of_week", s.t0.seconds_of_week()}};
  summary["simulated_s"] = ts_;
  summary["wall_s"] = wall_s;
  summary["flight_software"] = host_.software().describe();
  metrics_.add_to_summary(summary, {host_[0].name, host_[1].name});
  nlohmann::json files = nlohmann::json::array();
  for (const DataFileUse& f : sim::data_files_of(scenario_)) {
    files.push_back({{"key", f.key}, {"name", f.name}, {"path", f.path.empty() ? nlohmann::json() : nlohmann::json(f.path)},
                     {"bytes", f.size}, {"fnv1a64", f.checksum}});
  }
  summary["data_files"] = files;
  summary["embedded_defaults"] = fallbacks_;
  const AlignmentRequirements& requirements = metrics_.requirements();
  summary["requirements"] = {{"lateral_error_m", requirements.lateral_error_m},
                             {"lateral_velocity_mps", requirements.lateral_velocity_mps},
                             {"focus_error_m", requirements.focus_error_m},
                             {"safety_epsilon_m", s.gnc.safety.epsilon_m}};
  summary["truth"] = truth_summary();
  summary["paper_budget_mps"] = {{"standby_per_week", 0.3488}, {"transfer_to_science", 0.4934},
                                 {"transfer_to_standby", 0.4844}, {"science_per_observation", 0.0048}};
  summary["safety_violations"] = host_.safety_violations();
  summary["final_mode"] = to_string(host_[host_.active_index()].out.mode);
  const gnc::Telemetry& tm_dsc = host_[0].out.telemetry;
  const gnc::Telemetry& tm_osc = host_[1].out.telemetry;
  summary["rejected_inputs"] = tm_dsc.rejected.total() + tm_osc.rejected.total();
  for (std::size_t k = 0; k < 2; ++k) summary["inputs_refused"][std::string(host_[k].name)] = rejections_json(host_[k].out.telemetry.rejected);
  summary["planning_failures"] = tm_dsc.planning_failures + tm_osc.planning_failures;
  summary["navigation_mode"] = s.navigation_mode == NavigationMode::kCdgps ? "cdgps" : "ideal";
  if (sensors_.has_gps()) summary["navigation"] = metrics_.navigation_summary(host_);
  return summary;
}

core::Result<RunResult> run_campaign(const CampaignScenario& scenario, const std::filesystem::path& out_dir,
                                     const std::function<void(const RunProgress&)>& progress, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  const auto wall_s = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count(); };
  auto opened = RunRecorder::open(out_dir, campaign_to_toml(scenario));
  if (!opened.ok()) return opened.error();
  RunRecorder recorder = std::move(opened).value();
  auto created = CampaignSimulation::create(scenario, recorder, options);
  if (!created.ok()) return created.error();
  CampaignSimulation sim = std::move(created).value();
  for (std::int64_t steps = 0;; ++steps) {
    auto stepped = sim.step();
    if (!stepped.ok()) return stepped.error();
    if (!*stepped) break;
    if (progress && steps % 60 == 0) progress(RunProgress{sim.time_s(), sim.end_s(), wall_s()});
  }
  const nlohmann::json summary = sim.summary(wall_s());
  if (auto ok = recorder.finish(summary); !ok) return ok.error();
  return RunResult{summary, out_dir};
}

}  // namespace visors::sim
