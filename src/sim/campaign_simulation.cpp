#include "sim/campaign_simulation.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <type_traits>
#include <vector>
#include <cmath>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "astro/mean_osculating.hpp"
#include "astro/relative_orbital_elements.hpp"
#include "core/files/data_path.hpp"
#include "core/rtn_frame.hpp"
#include "sim/data_provenance.hpp"
#include "sim/flight_config.hpp"
#include "sim/formation_initial_state.hpp"
#include "sim/host_records.hpp"
#include "sim/navigation_message.hpp"
#include "sim/navigation_setup.hpp"

namespace visors::sim {

namespace {

using gnc::GroundCommand;
using gnc::Mode;
using gnc::Spacecraft;

// The host switches roles after the active spacecraft has reported GNC incapable this long [s].
constexpr double kRoleSwitchAfter_s = 60.0;
constexpr int kSolutionSatellites = 4;  // a receiver's position and time solution needs four

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

// The step of the timeline at `t_s` seconds since t0, or -1 for a negative (disabled) time.
std::int64_t step_at(double t_s, double step_s) {
  return t_s >= 0.0 ? static_cast<std::int64_t>(std::llround(t_s / step_s)) : -1;
}

// A burst of the garbage fault on every input channel: a record of random bytes behind a valid
// header (refused: bad checksum), and an intact record of NaN or out-of-range values (admitted,
// its values refused by validation).
void add_garbage(SimulatedSpacecraft& v, core::GpsTime t, RandomStream& rng, HostRecords& records) {
  for (int c = 1; c <= gnc::kChannels; ++c) {
    const auto channel = static_cast<gnc::Channel>(c);
    gnc::OutputRecords::Record r;
    r.size = gnc::record_size(channel);
    for (std::size_t i = 0; i < r.size; ++i) r.bytes[i] = static_cast<std::uint8_t>(rng.uniform() * 256.0);
    r.bytes[0] = 'V';
    r.bytes[1] = 'G';
    r.bytes[2] = static_cast<std::uint8_t>(c);
    r.bytes[3] = gnc::kRecordVersion;
    r.bytes[4] = static_cast<std::uint8_t>(r.size);
    r.bytes[5] = static_cast<std::uint8_t>(r.size >> 8);
    records.forward(r);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  records.add(v, gnc::TimeAtTone{t, Eigen::Quaterniond(nan, 0.0, 0.0, 0.0)});
  gnc::NavigationSolution navigation;
  navigation.t = t;
  navigation.chief_gcrf.r = Eigen::Vector3d::Constant(nan);
  records.add(v, navigation);
  records.add(v, gnc::GroundCommand{t, gnc::GroundCommand::Kind::kStartScience, -5});
  records.add(v, gnc::PropulsionTelemetry{t, Eigen::Vector3d::Zero(), nan, true});
  gnc::GpsMessage gps;
  gps.t = gps.epoch.t = t;
  gps.epoch.channel_count = 1;
  gps.epoch.channels[0].prn = 7;
  gps.epoch.channels[0].pseudorange_m = nan;
  records.add(v, gps);
  records.add(v, gnc::LaserRange{t, nan});
}

}  // namespace

CampaignSimulation::CampaignSimulation(const CampaignScenario& scenario, RunRecorder& recorder, const RunOptions& options)
    : scenario_(scenario),
      recorder_(&recorder),
      sky_(scenario.target_offset_rad),
      components_(std::make_unique<PairedWorker>(options.parallel_components)) {
  const CampaignScenario& s = scenario_;
  vehicles_[0].id = Spacecraft::kDsc;
  vehicles_[0].name = "dsc";
  vehicles_[1].id = Spacecraft::kOsc;
  vehicles_[1].name = "osc";
  observations_.reserve(static_cast<std::size_t>(s.observations) + 4);
  end_s_ = s.observations == 0 ? s.standby_s + s.tail_s : s.max_duration_s;
  steps_total_ = static_cast<std::int64_t>(std::floor(s.max_duration_s / s.step_s + 1e-9));
  output_every_ = static_cast<std::int64_t>(std::llround(s.output_step_s / s.step_s));
  science_step_ = static_cast<std::int64_t>(std::llround(s.standby_s / s.step_s));
  fault_step_ = step_at(s.fault.impulse_t_s, s.step_s);
  non_gnc_fault_step_ = step_at(s.fault.non_gnc_fault_t_s, s.step_s);
}

core::Result<CampaignSimulation> CampaignSimulation::create(const CampaignScenario& scenario, RunRecorder& recorder,
                                                           const RunOptions& options) {
  // Initial states: chief mean elements, deputy from the initial mean ROE.
  const auto initial = initial_formation_state(scenario);
  if (!initial.ok()) return initial.error();
  CampaignSimulation sim(scenario, recorder, options);
  if (scenario.navigation_mode == NavigationMode::kCdgps) {
    if (core::files::find_data_file(scenario.gnss.nav_file)) {
      if (auto ok = sim.set_up_gps(); !ok) return ok.error();
    } else {
      // Without the constellation there is no GPS to navigate with: the run goes on with ideal
      // navigation (the main command works without the shared data), loudly.
      sim.scenario_.navigation_mode = NavigationMode::kIdeal;
      sim.fallbacks_.push_back(fmt::format("gnss.nav_file '{}' not found in the data search path: no GPS constellation, "
                                           "so navigation mode cdgps falls back to ideal navigation (the [navigation] errors)",
                                           scenario.gnss.nav_file));
      recorder.event(0.0, "sim", "warning", sim.fallbacks_.back());
    }
  }
  // What the flight components are created with (the functions set_up_spacecraft uses).
  auto config = flight_config_json(sim.scenario_);
  if (!config.ok()) return config.error();
  if (auto ok = recorder.flight_config(config.value()); !ok) return ok.error();
  const GpsWorld* gps = sim.gps_ ? &*sim.gps_ : nullptr;
  SimulatedSpacecraft& dsc = sim.vehicles_[0];
  SimulatedSpacecraft& osc = sim.vehicles_[1];
  if (auto ok = set_up_spacecraft(dsc, scenario, scenario.dsc, scenario.active == "dsc", initial->dsc_gcrf, gps); !ok) {
    return ok.error();
  }
  if (auto ok = set_up_spacecraft(osc, scenario, scenario.osc, scenario.active == "osc", initial->osc_gcrf, gps); !ok) {
    return ok.error();
  }
  for (const SimulatedSpacecraft& v : sim.vehicles_) {
    const SpacecraftSettings& t = v.true_spacecraft;
    const double told_kg = v.id == Spacecraft::kDsc ? scenario.flight.dsc_mass_kg : scenario.flight.osc_mass_kg;
    recorder.event(0.0, v.name, "truth",
                   fmt::format("mass {:.4f} kg, Cd {:.4f}, Cr {:.4f} (the flight software is told {:.4f} kg, {:.4f}, {:.4f})",
                               t.mass_kg, t.cd, t.cr, told_kg, scenario.flight.cd, scenario.flight.cr));
    for (const auto& warning : v.truth.forces->warnings()) {
      recorder.event(0.0, v.name, "warning", warning);
      if (std::find(sim.fallbacks_.begin(), sim.fallbacks_.end(), warning) == sim.fallbacks_.end()) sim.fallbacks_.push_back(warning);
    }
  }
  return sim;
}

// The GPS world over the whole campaign, the data sets by satellite, the rangefinder's noise
// stream (as gnss-sim's) and navigation.csv.
core::Result<bool> CampaignSimulation::set_up_gps() {
  auto world = load_gps_world(scenario_, scenario_.max_duration_s);
  if (!world.ok()) return world.error();
  gps_.emplace(std::move(world).value());
  const auto records = gps_->satellites->broadcast_records();
  for (std::size_t i = 0; i < records.size(); ++i) sets_by_prn_[static_cast<std::size_t>(records[i].prn)].push_back(i);
  lrf_rng_.emplace(scenario_.seed, "osc.lrf");
  return recorder_->open_navigation();
}

SimulatedSpacecraft& CampaignSimulation::active() {
  return vehicles_[0].out.telemetry.active ? vehicles_[0] : vehicles_[1];
}

const SimulatedSpacecraft& CampaignSimulation::active() const {
  return vehicles_[0].out.telemetry.active ? vehicles_[0] : vehicles_[1];
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
  update_attitude(t);
  apply_ground_timeline(t);
  step_flight_components(t);
  score_navigation();
  // Per spacecraft, in order: the host routes its outputs, then applies its FDIR (the event log
  // keeps this order).
  route_outputs(vehicles_[0], vehicles_[1]);
  apply_fdir(vehicles_[0], vehicles_[1], t);
  route_outputs(vehicles_[1], vehicles_[0]);
  apply_fdir(vehicles_[1], vehicles_[0], t);
  inject_faults(t);
  record_metrics();
  update_end();
  if (auto ok = propagate_truth(t); !ok) return ok.error();
  ++k_;
  return true;
}

// Truth attitude: the commanded one (zenith pointing, slews for observations towards the target's
// apparent direction) with the ADCS's control error; the attitude the ADCS reports, with its
// determination error; the attitude-dependent drag area.
void CampaignSimulation::update_attitude(core::GpsTime t) {
  for (SimulatedSpacecraft& v : vehicles_) {
    v.target_unit_gcrf = sky_.target_unit_gcrf(t, v.x_gcrf);
    v.adcs->step(ts_);
    v.q_body_to_gcrf = v.adcs->true_attitude(v.attitude->body_to_gcrf(ts_, v.x_gcrf.r, v.x_gcrf.v, v.target_unit_gcrf));
    v.q_reported_body_to_gcrf = v.adcs->reported_attitude(v.q_body_to_gcrf);
    v.truth.forces->set_drag_area(v.drag.projected_area_m2(air_velocity_body_unit(v.x_gcrf, v.q_body_to_gcrf)));
  }
}

// Ground commands: to standby at t0, start science after standby_s.
void CampaignSimulation::apply_ground_timeline(core::GpsTime t) {
  if (k_ == 0) {
    for (SimulatedSpacecraft& v : vehicles_) v.command = GroundCommand{t, GroundCommand::Kind::kToStandby, 0};
  }
  if (k_ == science_step_ && scenario_.observations > 0) {
    for (SimulatedSpacecraft& v : vehicles_) v.command = GroundCommand{t, GroundCommand::Kind::kStartScience, scenario_.observations};
    science_started_ = true;
    recorder_->event(ts_, "sim", "command", fmt::format("start_science, {} observations", scenario_.observations));
  }
}

// Sensors (ideal navigation, or the GPS receivers and the rangefinder; the newest crosslink
// message, time at tone with the attitude) and one step of each flight component with the
// commands and telemetry queued for it.
void CampaignSimulation::step_flight_components(core::GpsTime t) {
  const core::StateVector& dsc_gcrf = vehicles_[0].x_gcrf;
  const core::StateVector& osc_gcrf = vehicles_[1].x_gcrf;
  const EpochFrame frame = gps_ ? epoch_frame(*gps_, t, earth_frame_) : EpochFrame{};
  open_fault_windows(t);
  close_fault_windows(t);
  // 1. Each component's input records (sensors, crosslink, commands): in order, since the
  //    sensors share the simulator's state (the constellation's caches, the scores, the events).
  std::array<bool, 2> stepped{};
  for (std::size_t k = 0; k < vehicles_.size(); ++k) {
    SimulatedSpacecraft& v = vehicles_[k];
    HostRecords& records = host_records_[k];
    records.clear();
    if (in_window(scenario_.fault.safe_mode, safe_mode_victim_, k)) {
      // Bus safe mode: the component is not stepped; nothing comes out of it.
      v.out.maneuver.reset();
      v.out.observation.reset();
      v.crosslink_out.size = 0;
      continue;
    }
    stepped[k] = true;
    records.add(v, gnc::TimeAtTone{t, v.q_reported_body_to_gcrf});
    bool solution = !gps_;  // ideal navigation: the receiver is not simulated, its PPS is
    if (gps_) {
      if (in_window(scenario_.fault.gps_outage, gps_outage_victim_, k)) {
        v.receiver->reacquire_all();  // the receiver restarts when the outage ends
      } else if (const auto gps = measure_gps(v, frame, t)) {
        records.add(v, *gps);
        solution = gps->epoch.channel_count >= kSolutionSatellites;
      }
      if (v.id == Spacecraft::kOsc) {
        if (const auto range = measure_range(t)) records.add(v, *range);
      }
    } else {
      records.add(v, v.navigation->solve(t, dsc_gcrf, osc_gcrf, k_ == 0 ? 0.0 : scenario_.step_s));
    }
    v.clock->tone(ts_, solution);
    for (const auto& delivered : v.inbox->receive(ts_)) records.forward(delivered);
    if (v.command) records.add(v, *v.command);
    if (v.telemetry) records.add(v, *v.telemetry);
    if (scenario_.fault.garbage.contains(ts_)) add_garbage(v, t, *garbage_rng_, records);
    v.command = v.command_after;
    v.command_after.reset();
    v.telemetry.reset();
  }
  // 2. The two flight components' steps, side by side (each owns all it touches).
  std::array<const gnc::OutputRecords*, 2> outputs{};
  const auto step = [&](std::size_t k) {
    if (!stepped[k]) return;
    const auto views = host_records_[k].views();
    const auto start = std::chrono::steady_clock::now();
    outputs[k] = &vehicles_[k].gnc->step(t, views);
    step_us_[k].push_back(static_cast<float>(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count()));
  };
  components_->run([&] { step(0); }, [&] { step(1); });
  // 3. Their outputs, in order.
  for (std::size_t k = 0; k < vehicles_.size(); ++k) {
    if (!stepped[k]) continue;
    SimulatedSpacecraft& v = vehicles_[k];
    const Mode before = v.out.mode;
    read_outputs(v, *outputs[k]);
    if (v.out.mode != before) recorder_->event(ts_, v.name, "mode", fmt::format("{} -> {}", to_string(before), to_string(v.out.mode)));
  }
}

void CampaignSimulation::read_outputs(SimulatedSpacecraft& v, const gnc::OutputRecords& out) {
  gnc::GncOutputs decoded;
  gnc::RecordHeader header;
  if (gnc::decode(out.telemetry.view(), decoded.telemetry, header) != gnc::RecordStatus::kAccepted) {
    recorder_->event(ts_, v.name, "rejected_message", "the component's telemetry record does not decode");
  }
  const gnc::Telemetry& tm = decoded.telemetry;
  decoded.mode = tm.mode;
  decoded.star_tracker_power = tm.star_tracker_power;
  decoded.lrf_power = tm.lrf_power;
  decoded.gnc_incapable = tm.gnc_incapable;
  decoded.passive_safety_violated = tm.passive_safety_violated;
  const auto optional_output = [&](const gnc::OutputRecords::Record& record, auto& slot, const char* name) {
    if (record.size == 0) return;
    typename std::decay_t<decltype(slot)>::value_type message;
    if (gnc::decode(record.view(), message, header) == gnc::RecordStatus::kAccepted) slot = message;
    else recorder_->event(ts_, v.name, "rejected_message", fmt::format("the component's {} record does not decode", name));
  };
  optional_output(out.maneuver, decoded.maneuver, "maneuver");
  optional_output(out.observation, decoded.observation, "observation");
  v.crosslink_out = out.crosslink;
  v.out = decoded;
}

// The receiver's epoch at t in the true pose (the attitude's rate from the spacecraft's attitude
// law), and the broadcast record it decoded; nothing in a data gap.
std::optional<gnc::GpsMessage> CampaignSimulation::measure_gps(SimulatedSpacecraft& v, const EpochFrame& frame, core::GpsTime t) {
  // The target's direction held over the rate's differencing interval (it turns ~1e-11 rad there).
  const auto law = [&](double t_s, const Eigen::Vector3d& r, const Eigen::Vector3d& velocity) {
    return v.attitude->body_to_gcrf(t_s, r, velocity, v.target_unit_gcrf);
  };
  const Eigen::Vector3d omega_gcrf = attitude_rate_gcrf(law, ts_, v.x_gcrf);
  const ReceiverPose pose = receiver_pose(frame, t, v.x_gcrf, v.q_body_to_gcrf, omega_gcrf, v.geometry->com_body_m());
  const GpsReceiverEpoch& epoch = v.receiver->measure(pose, *gps_->satellites);
  navigation_score_.record_phase_truth(v.id, epoch);
  if (!epoch.recorded) return std::nullopt;
  gnc::GpsMessage message;
  message.t = epoch.measurement.t;
  message.epoch = epoch.measurement;
  decode_ephemeris(v, t, message);
  return message;
}

// At most one broadcast record per message: of the first tracked satellite whose data set in
// force at t (each from t_oe - refresh_s / 2, the first from the start: the receivers of
// gnss-sim select the same way) the receiver has not passed on yet and has decoded by t: its
// subframes 1-3 received whole since the later of the lock and the set's first broadcast
// (sim/navigation_message.hpp: 18-36 s).
void CampaignSimulation::decode_ephemeris(SimulatedSpacecraft& v, core::GpsTime t, gnc::GpsMessage& message) {
  const auto records = gps_->satellites->broadcast_records();
  const double half_refresh_s = 0.5 * scenario_.gnss.broadcast_errors.refresh_s;
  for (int k = 0; k < message.epoch.channel_count; ++k) {
    const auto prn = static_cast<std::size_t>(message.epoch.channels[static_cast<std::size_t>(k)].prn);
    const std::vector<std::size_t>& sets = sets_by_prn_[prn];
    std::size_t& next = v.next_ephemeris[prn];
    std::size_t current = next > 0 ? next - 1 : 0;
    while (current + 1 < sets.size() && half_refresh_s > 0.0 && t.seconds_since(records[sets[current + 1]].toe) >= -half_refresh_s) {
      ++current;
    }
    if (sets.empty() || next > current) continue;
    const double lock_start_s = t.seconds() - message.epoch.channels[static_cast<std::size_t>(k)].lock_time_s;
    const double broadcast_from_s = current == 0 ? lock_start_s : records[sets[current]].toe.seconds() - half_refresh_s;
    if (t.seconds() < ephemeris_decoded_at(std::max(lock_start_s, broadcast_from_s))) continue;
    message.has_ephemeris = true;
    message.ephemeris = records[sets[current]];
    next = current + 1;
    return;
  }
}

// The OSC's rangefinder while its component powers it, inside an observation window, every
// [gnss.lrf] interval_s from the window's first step: the range between the true payload points
// with [gnss.lrf] bias_m and N(0, sigma_m) noise (as gnss-sim's lrf.csv).
std::optional<gnc::LaserRange> CampaignSimulation::measure_range(core::GpsTime t) {
  const SimulatedSpacecraft& dsc = vehicles_[0];
  const SimulatedSpacecraft& osc = vehicles_[1];
  if (!osc.out.lrf_power) return std::nullopt;
  const GnssLrfSettings& lrf = scenario_.gnss.lrf;
  const auto stride = std::max<std::int64_t>(1, std::llround(lrf.interval_s / scenario_.step_s));
  for (const ObservationWindow& w : osc.attitude->windows()) {
    if (ts_ < w.start_s - 1e-9 || ts_ > w.end_s + 1e-9) continue;
    const auto first = static_cast<std::int64_t>(std::ceil(w.start_s / scenario_.step_s - 1e-9));
    if ((k_ - first) % stride != 0) return std::nullopt;
    const Eigen::Vector3d p_osc = osc.x_gcrf.r + osc.q_body_to_gcrf * osc.geometry->payload_from_com_body_m();
    const Eigen::Vector3d p_dsc = dsc.x_gcrf.r + dsc.q_body_to_gcrf * dsc.geometry->payload_from_com_body_m();
    return gnc::LaserRange{t, (p_osc - p_dsc).norm() + lrf.bias_m + lrf_rng_->normal(lrf.sigma_m)};
  }
  return std::nullopt;
}

// Where the observations are (the active spacecraft's schedule, which the passive one follows):
// in a window, or in the slew to it or back from it (as long as the slew to it).
bool CampaignSimulation::in_observation(double t_s) const {
  for (const ObservationWindow& w : active().attitude->windows()) {
    if (t_s >= w.start_s && t_s <= w.end_s) return true;
  }
  return false;
}

bool CampaignSimulation::in_slew(double t_s) const {
  for (const ObservationWindow& w : active().attitude->windows()) {
    const double lead = w.start_s - w.slew_start_s;
    if ((t_s >= w.slew_start_s && t_s < w.start_s) || (t_s > w.end_s && t_s <= w.end_s + lead)) return true;
  }
  return false;
}

// Each component's navigation solution of this step against the truth.
void CampaignSimulation::score_navigation() {
  if (!gps_) return;
  const SimulatedSpacecraft& dsc = vehicles_[0];
  const SimulatedSpacecraft& osc = vehicles_[1];
  FormationTruth truth;
  truth.dsc_gcrf = dsc.x_gcrf;
  truth.osc_gcrf = osc.x_gcrf;
  truth.dsc_body_to_gcrf = dsc.q_body_to_gcrf.toRotationMatrix();
  truth.osc_body_to_gcrf = osc.q_body_to_gcrf.toRotationMatrix();
  // True minus known lever arm from the centre of mass to the phase centre: the known one is the
  // flight software's, the true one the receiver's (drawn centre of mass, tilted boresight,
  // phase-centre error).
  const Eigen::Vector3d known = known_antenna_lever_body_m();
  const auto lever_error = [&known](const SimulatedSpacecraft& v) -> Eigen::Vector3d {
    return (v.receiver->phase_center_body_m() - v.geometry->com_body_m()) - known;
  };
  truth.dsc_lever_error_m = lever_error(dsc);
  truth.osc_lever_error_m = lever_error(osc);
  const bool slewing = in_slew(ts_);
  for (std::size_t k = 0; k < 2; ++k) {
    const SimulatedSpacecraft& v = vehicles_[k];
    const auto& navigation = v.gnc->component().navigation();
    if (!navigation) continue;
    navigation_samples_[k] = navigation_score_.score(v.id, *navigation, ts_, truth, slewing);
  }
}

// Host routing: crosslink to the other spacecraft, observation schedule to the attitude profile
// (and, from the active spacecraft, to the metrics), maneuvers to the propulsion.
void CampaignSimulation::route_outputs(SimulatedSpacecraft& v, SimulatedSpacecraft& other) {
  if (v.crosslink_out.size > 0 && !scenario_.fault.crosslink_loss.contains(ts_)) other.inbox->send(ts_, v.crosslink_out);
  if (v.out.observation) {
    const auto& o = *v.out.observation;
    const core::GpsTime t0 = scenario_.t0;
    const ObservationWindow window{o.slew_start.seconds_since(t0), o.start.seconds_since(t0), o.end.seconds_since(t0)};
    if (auto ok = v.attitude->schedule(window); !ok) recorder_->event(ts_, v.name, "rejected_message", ok.error().describe());
    if (v.out.telemetry.active) {
      PendingObservation p;
      p.result.index = o.index;
      p.result.t_s = window.start_s;
      p.start_s = window.start_s;
      p.end_s = window.end_s;
      observations_.push_back(p);
      const auto& target = v.out.telemetry.roe_target_m;
      recorder_->event(ts_, v.name, "observation",
                       fmt::format("attempt {} scheduled at t = {:.1f} s, target a*roe = [{:.3f}, {:.3f}, {:.3f}, {:.3f}, {:.3f}, {:.3f}] m",
                                   o.index, window.start_s, target(0), target(1), target(2), target(3), target(4), target(5)));
    }
  }
  if (v.out.maneuver) execute_maneuver(v, scenario_.t0 + ts_);
}

// The propulsion executes the commanded impulse (with its errors) on the truth; its telemetry
// goes back at the next step.
void CampaignSimulation::execute_maneuver(SimulatedSpacecraft& v, core::GpsTime t) {
  const Mode mode = v.out.mode;
  gnc::PropulsionTelemetry telemetry;
  telemetry.t = t;
  telemetry.mass_kg = v.propulsion->mass_kg();
  if (thruster_victim_ >= 0 && &v == &vehicles_[static_cast<std::size_t>(thruster_victim_)]) {
    // A failed thruster: nothing executed, the telemetry says so, and the host's FDIR (once).
    v.telemetry = telemetry;
    if (v.out.telemetry.active) switch_away_from(static_cast<std::size_t>(thruster_victim_), t + scenario_.step_s, "thruster failed");
    return;
  }
  auto executed = v.propulsion->execute(ts_, v.out.maneuver->dv_body_mps);
  if (executed.ok()) {
    // Executed at the tone's true instant, offset_s after t (sim/host_clock.hpp).
    const Eigen::Vector3d dv_gcrf = v.q_body_to_gcrf * executed->dv_executed_body_mps;
    v.x_gcrf.v += dv_gcrf;
    v.x_gcrf.r -= v.clock->offset_s() * dv_gcrf;
    const double l1 = thruster_l1_norm(executed->dv_executed_body_mps);
    v.dv_by_mode_mps[static_cast<std::size_t>(mode)] += l1;
    v.dv_total_mps += l1;
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

// Host FDIR on the active spacecraft's outputs (mission paper): a passive-safety violation ->
// escape; GNC incapable for kRoleSwitchAfter_s while the other is capable (and not in a bus safe
// mode, whose last outputs are stale) -> role switch.
void CampaignSimulation::apply_fdir(SimulatedSpacecraft& v, SimulatedSpacecraft& other, core::GpsTime t) {
  if (!v.out.telemetry.active) return;
  const core::GpsTime next = t + scenario_.step_s;
  if (v.out.passive_safety_violated && !v.violation_reported) {
    v.violation_reported = true;
    ++safety_violations_;
    v.command = GroundCommand{next, GroundCommand::Kind::kEscape, 0};
    recorder_->event(ts_, v.name, "safety_violation",
                     fmt::format("passive-safety margin {:.3f} m below epsilon; host commands escape", v.out.telemetry.safety_margin_m));
  }
  if (!v.out.passive_safety_violated) v.violation_reported = false;
  if (!v.out.gnc_incapable) {
    v.incapable_since_s = -1.0;
    return;
  }
  if (v.incapable_since_s < 0.0) v.incapable_since_s = ts_;
  const auto other_index = static_cast<std::size_t>(&other == &vehicles_[0] ? 0 : 1);
  const bool other_in_safe_mode = in_window(scenario_.fault.safe_mode, safe_mode_victim_, other_index);
  if (ts_ - v.incapable_since_s >= kRoleSwitchAfter_s && !other.out.gnc_incapable && !other_in_safe_mode) {
    v.command = GroundCommand{next, GroundCommand::Kind::kMakePassive, 0};
    other.command = GroundCommand{next, GroundCommand::Kind::kMakeActive, 0};
    v.incapable_since_s = -1.0;
    recorder_->event(ts_, "sim", "fdir", fmt::format("{} GNC incapable: role switch", v.name));
  }
}

// The fault windows that open at this step: each concerns the spacecraft active then. A bus safe
// mode is the non-GNC fault of mission paper's FDIR with the spacecraft unable to act: the host
// switches roles at once and, from science or a transfer, commands the new active spacecraft back
// to standby at the next step (one command a step).
void CampaignSimulation::open_fault_windows(core::GpsTime t) {
  const FaultSettings& f = scenario_.fault;
  const int active_index = &active() == &vehicles_[0] ? 0 : 1;
  if (f.gps_outage.contains(ts_) && gps_outage_victim_ < 0) {
    gps_outage_victim_ = active_index;
    recorder_->event(ts_, vehicles_[static_cast<std::size_t>(active_index)].name, "fault",
                     fmt::format("GPS receiver outage for {:.0f} s", f.gps_outage.duration_s));
  }
  if (f.crosslink_loss.contains(ts_) && !f.crosslink_loss.contains(ts_ - scenario_.step_s)) {
    recorder_->event(ts_, "sim", "fault", fmt::format("crosslink lost for {:.0f} s", f.crosslink_loss.duration_s));
  }
  if (f.garbage.contains(ts_) && !garbage_rng_) {
    garbage_rng_.emplace(scenario_.seed, "faults.garbage");
    recorder_->event(ts_, "sim", "fault", fmt::format("garbage and NaN records on every channel for {:.0f} s", f.garbage.duration_s));
  }
  if (f.safe_mode.contains(ts_) && safe_mode_victim_ < 0) {
    safe_mode_victim_ = active_index;
    recorder_->event(ts_, vehicles_[static_cast<std::size_t>(active_index)].name, "fault",
                     fmt::format("bus safe mode for {:.0f} s", f.safe_mode.duration_s));
    switch_away_from(static_cast<std::size_t>(active_index), t, "in bus safe mode");
  }
  if (f.thruster_failure_t_s >= 0.0 && ts_ >= f.thruster_failure_t_s && thruster_victim_ < 0) {
    thruster_victim_ = active_index;
    recorder_->event(ts_, vehicles_[static_cast<std::size_t>(active_index)].name, "fault", "thruster failed");
  }
  if (gps_ && f.clock_jump_t_s >= 0.0 && k_ == step_at(f.clock_jump_t_s, scenario_.step_s)) {
    SimulatedSpacecraft& v = vehicles_[static_cast<std::size_t>(active_index)];
    v.receiver->jump_clock(f.clock_jump_m);
    recorder_->event(ts_, v.name, "fault", fmt::format("receiver clock jump of {:.3f} m", f.clock_jump_m));
  }
}

// The host's response to a non-GNC fault that leaves a spacecraft unable to act (mission paper's
// FDIR: from science or a transfer back to standby, else a role switch; here the role switch in
// any case, the faulty one cannot fly the return): the other made active at once and, from
// science or a transfer, commanded back to standby at the next step (one command a step).
void CampaignSimulation::switch_away_from(std::size_t victim_index, core::GpsTime t, std::string_view what) {
  SimulatedSpacecraft& victim = vehicles_[victim_index];
  SimulatedSpacecraft& other = vehicles_[1 - victim_index];
  const Mode mode_now = victim.out.mode;
  victim.command = GroundCommand{t, GroundCommand::Kind::kMakePassive, 0};
  other.command = GroundCommand{t, GroundCommand::Kind::kMakeActive, 0};
  if (mode_now == Mode::kScience || mode_now == Mode::kTransferToScience) {
    other.command_after = GroundCommand{t + scenario_.step_s, GroundCommand::Kind::kTransferToStandby, 0};
    recorder_->event(ts_, "sim", "fdir", fmt::format("{} {}: role switch, then transfer to standby", victim.name, what));
  } else {
    recorder_->event(ts_, "sim", "fdir", fmt::format("{} {}: role switch", victim.name, what));
  }
}

bool CampaignSimulation::in_window(const FaultWindow& window, int victim, std::size_t k) const {
  return victim == static_cast<int>(k) && window.contains(ts_);
}

// The first step after a safe mode: the spacecraft is back, and told it is passive now.
void CampaignSimulation::close_fault_windows(core::GpsTime t) {
  const FaultWindow& safe = scenario_.fault.safe_mode;
  if (safe_mode_victim_ >= 0 && !safe.contains(ts_) && safe.contains(ts_ - scenario_.step_s)) {
    SimulatedSpacecraft& back = vehicles_[static_cast<std::size_t>(safe_mode_victim_)];
    back.command = GroundCommand{t, GroundCommand::Kind::kMakePassive, 0};
    recorder_->event(ts_, back.name, "fault", "back from bus safe mode: made passive");
  }
}


// Scenario faults: a non-GNC fault reported to the host (its FDIR: back to standby from science
// or transfer, else a role switch), and an unplanned impulse on the OSC's truth.
void CampaignSimulation::inject_faults(core::GpsTime t) {
  if (k_ == non_gnc_fault_step_) {
    SimulatedSpacecraft& active_now = active();
    SimulatedSpacecraft& passive_now = &active_now == &vehicles_[0] ? vehicles_[1] : vehicles_[0];
    const Mode mode_now = active_now.out.mode;
    const core::GpsTime next = t + scenario_.step_s;
    if (mode_now == Mode::kScience || mode_now == Mode::kTransferToScience) {
      active_now.command = GroundCommand{next, GroundCommand::Kind::kTransferToStandby, 0};
      recorder_->event(ts_, "sim", "fdir", "non-GNC fault: transfer to standby");
    } else {
      active_now.command = GroundCommand{next, GroundCommand::Kind::kMakePassive, 0};
      passive_now.command = GroundCommand{next, GroundCommand::Kind::kMakeActive, 0};
      recorder_->event(ts_, "sim", "fdir", "non-GNC fault: role switch");
    }
  }
  if (k_ == fault_step_) {
    SimulatedSpacecraft& osc = vehicles_[1];
    const Eigen::Matrix3d rtn_to_gcrf = core::gcrf_to_rtn_matrix(osc.x_gcrf).transpose();
    osc.x_gcrf.v += rtn_to_gcrf * scenario_.fault.impulse_dv_rtn_mps;
    recorder_->event(ts_, "osc", "fault", "unplanned impulse dv_rtn = " + vector_text(scenario_.fault.impulse_dv_rtn_mps, 1e3) + " mm/s");
  }
}

// Alignment samples of the observations in progress (payload reference points with the drawn
// geometry errors), closing those that ended; minimum separations every step; the time series
// every output step.
void CampaignSimulation::record_metrics() {
  const SimulatedSpacecraft& dsc = vehicles_[0];
  const SimulatedSpacecraft& osc = vehicles_[1];
  for (PendingObservation& p : observations_) {
    if (p.done) continue;
    if (ts_ >= p.start_s && ts_ <= p.end_s) {
      const Eigen::Vector3d p_osc = osc.x_gcrf.r + osc.q_body_to_gcrf * osc.geometry->payload_from_com_body_m();
      const Eigen::Vector3d p_dsc = dsc.x_gcrf.r + dsc.q_body_to_gcrf * dsc.geometry->payload_from_com_body_m();
      const AlignmentSample sample =
          add_alignment_sample(p.result, p_osc, osc.x_gcrf.v, p_dsc, dsc.x_gcrf.v, dsc.target_unit_gcrf, requirements_);
      recorder_->alignment_sample(p.result.index, ts_, dsc.x_gcrf, dsc.q_body_to_gcrf, osc.x_gcrf, osc.q_body_to_gcrf,
                                  dsc.target_unit_gcrf, sample);
      for (std::size_t k = 0; k < 2; ++k) {
        const SimulatedSpacecraft& v = vehicles_[k];
        const Eigen::Vector3d los_gcrf = v.q_body_to_gcrf * v.geometry->payload_axis_body();
        const double angle = std::atan2(los_gcrf.cross(v.target_unit_gcrf).norm(), los_gcrf.dot(v.target_unit_gcrf));
        p.result.payload_pointing_rad(static_cast<Eigen::Index>(k)) = std::max(p.result.payload_pointing_rad(static_cast<Eigen::Index>(k)), angle);
      }
    } else if (ts_ > p.end_s) {
      p.done = true;
      const bool ok = p.result.success(requirements_);
      recorder_->observation(p.result, ok);
      recorder_->event(ts_, "sim", "observation",
                       fmt::format("attempt {}: lateral {:.2f} mm, lateral velocity {:.3f} mm/s, focus {:.2f} mm: {}", p.result.index,
                                   1e3 * p.result.lateral_error_m, 1e3 * p.result.lateral_velocity_mps,
                                   1e3 * p.result.focus_error_m, ok ? "success" : "failure"));
    }
  }
  TimeseriesRow row = truth_geometry(dsc.x_gcrf, osc.x_gcrf);
  min_sep_rn_m_ = std::min(min_sep_rn_m_, row.sep_rn_m);
  min_sep_3d_m_ = std::min(min_sep_3d_m_, row.sep_3d_m);
  if (k_ % output_every_ != 0) return;
  const SimulatedSpacecraft& now = active();
  add_truth_roe(dsc.x_gcrf, osc.x_gcrf, scenario_.gnc.gravity, row);
  row.t_s = ts_;
  row.mode = to_string(now.out.mode);
  row.active = now.name;
  row.has_margin = now.out.telemetry.safety_checked;
  row.safety_margin_m = now.out.telemetry.safety_margin_m;
  row.dv_dsc_mps = dsc.dv_total_mps;
  row.dv_osc_mps = osc.dv_total_mps;
  recorder_->timeseries(row);
  if (!gps_) return;
  const bool slewing = in_slew(ts_), observing = in_observation(ts_);
  for (std::size_t k = 0; k < 2; ++k) {
    const SimulatedSpacecraft& v = vehicles_[k];
    const gnc::NavigationCounters& c = v.gnc->component().navigation()->counters();
    const std::int64_t epochs = c.epochs_joint + c.epochs_alone;
    const double fixed_fraction = epochs > rows_epochs_[k] ? static_cast<double>(c.epochs_fixed - rows_fixed_[k]) /
                                                                 static_cast<double>(epochs - rows_epochs_[k])
                                                           : 0.0;
    rows_epochs_[k] = epochs;
    rows_fixed_[k] = c.epochs_fixed;
    recorder_->navigation(ts_, v.name, navigation_samples_[k], fixed_fraction, slewing, observing);
  }
}

// The campaign ends tail_s after the active spacecraft is back in standby after science, or in
// manual after an escape.
void CampaignSimulation::update_end() {
  const Mode mode = active().out.mode;
  if (science_started_ && (mode == Mode::kTransferToStandby || mode == Mode::kScience)) left_science_ = true;
  if (!escaped_ && mode == Mode::kEscape) escaped_ = true;
  if (end_s_ >= scenario_.max_duration_s && ((left_science_ && mode == Mode::kStandby) || (escaped_ && mode == Mode::kManual))) {
    end_s_ = ts_ + scenario_.tail_s;
  }
}

core::Result<bool> CampaignSimulation::propagate_truth(core::GpsTime t) {
  for (SimulatedSpacecraft& v : vehicles_) {
    auto next = v.truth.propagator->propagate_to(t, v.x_gcrf, t + scenario_.step_s);
    if (!next.ok()) return core::Error{std::string(v.name) + " truth", next.error().describe()};
    v.x_gcrf = *next;
  }
  return true;
}

// What the run drew for each spacecraft (docs/run-directory.md "truth"): the body vectors from the
// structural origin (true centre of mass, payload reference point and line of sight, GPS phase
// centre), the true mass, Cd, Cr and the propulsion's Isp and nozzle biases.
nlohmann::json CampaignSimulation::truth_summary() const {
  const auto vector = [](const Eigen::Vector3d& x) { return nlohmann::json::array({x.x(), x.y(), x.z()}); };
  nlohmann::json out;
  for (const SimulatedSpacecraft& v : vehicles_) {
    nlohmann::json t{{"com_body_m", vector(v.geometry->com_body_m())},
                     {"payload_body_m", vector(v.geometry->payload_body_m())},
                     {"payload_axis_body", vector(v.geometry->payload_axis_body())},
                     {"phase_center_error_body_m", vector(v.geometry->phase_center_error_body_m())},
                     {"mass_kg", v.true_spacecraft.mass_kg},
                     {"cd", v.true_spacecraft.cd},
                     {"cr", v.true_spacecraft.cr},
                     {"isp_s", v.propulsion->isp_s()},
                     {"nozzle_bias", v.propulsion->nozzle_bias()},
                     {"clock_frequency_error", v.clock->frequency_error()},
                     {"clock_max_abs_offset_s", v.clock->max_abs_offset_s()}};
    if (v.receiver) t["phase_center_body_m"] = vector(v.receiver->phase_center_body_m());
    out[std::string(v.name)] = t;
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
  nlohmann::json list = nlohmann::json::array();
  int successes = 0, attempts = 0;
  for (const PendingObservation& p : observations_) {
    if (!p.done) continue;
    const bool ok = p.result.success(requirements_);
    successes += ok ? 1 : 0;
    ++attempts;
    list.push_back({{"index", p.result.index}, {"t_s", p.result.t_s}, {"lateral_error_m", p.result.lateral_error_m},
                    {"lateral_velocity_mps", p.result.lateral_velocity_mps}, {"focus_error_m", p.result.focus_error_m},
                    {"lateral_x_m", p.result.lateral_detector_m.x()}, {"lateral_y_m", p.result.lateral_detector_m.y()},
                    {"focus_signed_m", p.result.focus_signed_m}, {"success", ok}});
  }
  summary["observations"] = list;
  summary["success_rate"] = attempts > 0 ? static_cast<double>(successes) / attempts : 0.0;
  nlohmann::json files = nlohmann::json::array();
  for (const DataFileUse& f : sim::data_files_of(scenario_)) {
    files.push_back({{"key", f.key}, {"name", f.name}, {"path", f.path.empty() ? nlohmann::json() : nlohmann::json(f.path)},
                     {"bytes", f.size}, {"fnv1a64", f.checksum}});
  }
  summary["data_files"] = files;
  summary["embedded_defaults"] = fallbacks_;
  summary["requirements"] = {{"lateral_error_m", requirements_.lateral_error_m},
                             {"lateral_velocity_mps", requirements_.lateral_velocity_mps},
                             {"focus_error_m", requirements_.focus_error_m},
                             {"safety_epsilon_m", s.gnc.safety.epsilon_m}};
  nlohmann::json dv;
  for (const SimulatedSpacecraft& v : vehicles_) {
    nlohmann::json by_mode;
    for (int m = 0; m < gnc::kModeCount; ++m) by_mode[std::string(to_string(static_cast<Mode>(m)))] = v.dv_by_mode_mps[static_cast<std::size_t>(m)];
    by_mode["total"] = v.dv_total_mps;
    dv[std::string(v.name)] = by_mode;
  }
  summary["delta_v_mps"] = dv;
  summary["truth"] = truth_summary();
  summary["paper_budget_mps"] = {{"standby_per_week", 0.3488}, {"transfer_to_science", 0.4934},
                                 {"transfer_to_standby", 0.4844}, {"science_per_observation", 0.0048}};
  summary["min_separation_rn_m"] = min_sep_rn_m_;
  summary["min_separation_3d_m"] = min_sep_3d_m_;
  summary["safety_violations"] = safety_violations_;
  summary["final_mode"] = to_string(active().out.mode);
  const gnc::Telemetry& tm_dsc = vehicles_[0].out.telemetry;
  const gnc::Telemetry& tm_osc = vehicles_[1].out.telemetry;
  summary["rejected_inputs"] = tm_dsc.rejected.total() + tm_osc.rejected.total();
  for (const SimulatedSpacecraft& v : vehicles_) {
    nlohmann::json refused;
    const auto& by_status = v.out.telemetry.records.by_status;
    for (std::size_t k = 1; k < by_status.size(); ++k) refused[std::string(gnc::to_string(static_cast<gnc::RecordStatus>(k)))] = by_status[k];
    summary["records_refused"][std::string(v.name)] = refused;
  }
  summary["planning_failures"] = tm_dsc.planning_failures + tm_osc.planning_failures;
  summary["navigation_mode"] = s.navigation_mode == NavigationMode::kCdgps ? "cdgps" : "ideal";
  for (std::size_t k = 0; k < vehicles_.size(); ++k) {
    // Wall time of each flight-component step through its binary interface (decoding, the step,
    // encoding) [us]: the flight rule's budget is a median <= 0.3 ms and a 99.9th percentile <= 5 ms.
    std::vector<float> sorted = step_us_[k];
    std::sort(sorted.begin(), sorted.end());
    const auto at = [&sorted](double q) {
      return sorted.empty() ? 0.0 : static_cast<double>(sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))]);
    };
    summary["flight_step_us"][std::string(vehicles_[k].name)] = {{"median", at(0.5)}, {"p99_9", at(0.999)}, {"max", at(1.0)}};
  }
  if (gps_) summary["navigation"] = navigation_summary();
  return summary;
}

// The navigation score (sim/navigation_score.hpp) with each component's counters.
nlohmann::json CampaignSimulation::navigation_summary() const {
  nlohmann::json out = navigation_score_.summary();
  for (const SimulatedSpacecraft& v : vehicles_) {
    const gnc::NavigationCounters& c = v.gnc->component().navigation()->counters();
    nlohmann::json ephemerides;
    for (int k = 0; k < static_cast<int>(c.ephemerides.size()); ++k) {
      ephemerides[gnss::to_string(static_cast<gnss::EphemerisStore::AcceptStatus>(k))] = c.ephemerides[static_cast<std::size_t>(k)];
    }
    nlohmann::json& n = out[std::string(v.name)];
    n["epochs_joint"] = c.epochs_joint;
    n["epochs_alone"] = c.epochs_alone;
    n["epochs_refused"] = c.epochs_refused;
    n["wrong_fixes_refused"] = c.wrong_fixes_refused;
    n["impulses_applied"] = c.impulses_applied;
    n["impulses_late"] = c.impulses_late;
    n["laser_ranges_used"] = c.laser_used;
    n["laser_ranges_rejected"] = c.laser_rejected;
    n["clock_jumps"] = c.clock_jumps;
    n["ephemerides"] = ephemerides;
    n["rejected_gps_messages"] = v.out.telemetry.rejected.gps;
  }
  return out;
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
