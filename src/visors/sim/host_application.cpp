#include "visors/sim/host_application.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

namespace visors::sim {
namespace {

using gnc::GroundCommand;
using gnc::Mode;

core::Result<bool> set_up_crosslink(HostedComponent& c, const CampaignScenario& s) {
  CrosslinkSettings link;
  link.delay_s = s.crosslink_delay_s;
  link.drop_probability = s.crosslink_drop_probability;
  auto inbox = Crosslink<gnc::OutputRecords::Record>::create(link, RandomStream(s.seed, std::string(c.name) + ".crosslink"));
  if (!inbox.ok()) return core::Error{"crosslink." + inbox.error().field, inbox.error().message};
  c.inbox.emplace(std::move(inbox).value());
  return true;
}

std::string_view response_text(FdirResponse response) {
  switch (response) {
    case FdirResponse::kEscape: return "escape";
    case FdirResponse::kRoleSwitch: return "role switch";
    case FdirResponse::kTransferToStandby: return "transfer to standby";
    case FdirResponse::kRoleSwitchThenStandby: return "role switch, then transfer to standby";
  }
  return "";
}

}  // namespace

FdirResponse fdir_response(FdirTrigger trigger, Mode mode) {
  const bool in_science = mode == Mode::kScience || mode == Mode::kTransferToScience;
  for (const FdirRule& rule : kFdirPolicy) {
    if (rule.trigger == trigger) return in_science ? rule.in_science : rule.otherwise;
  }
  return FdirResponse::kRoleSwitch;  // unreachable: every trigger has a rule (a test checks)
}

HostApplication::HostApplication(const CampaignScenario& s, RunRecorder& recorder, FlightSoftware software)
    : recorder_(&recorder),
      scenario_fault_(s.fault),
      step_s_(s.step_s),
      observations_(s.observations),
      science_step_(static_cast<std::int64_t>(std::llround(s.standby_s / s.step_s))),
      clock_jump_step_(step_at(s.fault.clock_jump_t_s, s.step_s)),
      seed_(s.seed),
      software_(std::move(software)) {
  craft_[0].id = gnc::Spacecraft::kDsc;
  craft_[0].name = "dsc";
  craft_[1].id = gnc::Spacecraft::kOsc;
  craft_[1].name = "osc";
}

core::Result<HostApplication> HostApplication::create(const CampaignScenario& scenario, RunRecorder& recorder, bool gps,
                                                      FlightSoftware software) {
  HostApplication host(scenario, recorder, std::move(software));
  host.gps_ = gps;
  for (HostedComponent& c : host.craft_) {
    if (auto ok = set_up_crosslink(c, scenario); !ok) return ok.error();
  }
  return host;
}

void HostApplication::command(std::size_t k, GroundCommand::Kind kind, core::GpsTime at) {
  craft_[k].command = GroundCommand{at, kind, 0};
}

void HostApplication::apply_ground_timeline(std::int64_t step, core::GpsTime t, double t_s) {
  if (step == 0) {
    for (std::size_t k = 0; k < 2; ++k) command(k, GroundCommand::Kind::kToStandby, t);
  }
  if (step == science_step_ && observations_ > 0) {
    for (HostedComponent& c : craft_) c.command = GroundCommand{t, GroundCommand::Kind::kStartScience, observations_};
    science_started_ = true;
    recorder_->event(t_s, "sim", "command", fmt::format("start_science, {} observations", observations_));
  }
}

std::optional<std::size_t> HostApplication::open_fault_windows(std::int64_t step, core::GpsTime t, double t_s) {
  const FaultSettings& f = scenario_fault_;
  const auto active = static_cast<int>(active_index());
  const std::string_view active_name = craft_[static_cast<std::size_t>(active)].name;
  if (f.gps_outage.contains(t_s) && gps_outage_victim_ < 0) {
    gps_outage_victim_ = active;
    recorder_->event(t_s, active_name, "fault", fmt::format("GPS receiver outage for {:.0f} s", f.gps_outage.duration_s));
  }
  if (f.crosslink_loss.contains(t_s) && !f.crosslink_loss.contains(t_s - step_s_)) {
    recorder_->event(t_s, "sim", "fault", fmt::format("crosslink lost for {:.0f} s", f.crosslink_loss.duration_s));
  }
  if (f.garbage.contains(t_s) && !garbage_rng_) {
    garbage_rng_.emplace(seed_, "faults.garbage");
    recorder_->event(t_s, "sim", "fault", fmt::format("garbage and NaN records on every channel for {:.0f} s", f.garbage.duration_s));
  }
  if (f.safe_mode.contains(t_s) && safe_mode_victim_ < 0) {
    safe_mode_victim_ = active;
    recorder_->event(t_s, active_name, "fault", fmt::format("bus safe mode for {:.0f} s", f.safe_mode.duration_s));
    respond(FdirTrigger::kUnableToAct, static_cast<std::size_t>(active), t, t_s, fmt::format("{} in bus safe mode", active_name));
  }
  if (f.thruster_failure_t_s >= 0.0 && t_s >= f.thruster_failure_t_s && thruster_victim_ < 0) {
    thruster_victim_ = active;
    recorder_->event(t_s, active_name, "fault", "thruster failed");
  }
  if (gps_ && step == clock_jump_step_) {
    recorder_->event(t_s, active_name, "fault", fmt::format("receiver clock jump of {:.3f} m", f.clock_jump_m));
    return static_cast<std::size_t>(active);
  }
  return std::nullopt;
}

void HostApplication::close_fault_windows(core::GpsTime t, double t_s) {
  const FaultWindow& safe = scenario_fault_.safe_mode;
  if (safe_mode_victim_ >= 0 && !safe.contains(t_s) && safe.contains(t_s - step_s_)) {
    const auto back = static_cast<std::size_t>(safe_mode_victim_);
    command(back, GroundCommand::Kind::kMakePassive, t);
    recorder_->event(t_s, craft_[back].name, "fault", "back from bus safe mode: made passive");
  }
}

bool HostApplication::in_safe_mode(std::size_t k, double t_s) const {
  return safe_mode_victim_ == static_cast<int>(k) && scenario_fault_.safe_mode.contains(t_s);
}

bool HostApplication::in_gps_outage(std::size_t k, double t_s) const {
  return gps_outage_victim_ == static_cast<int>(k) && scenario_fault_.gps_outage.contains(t_s);
}

// A burst of the garbage fault on every input channel: a record of random bytes behind a valid
// header (refused: bad checksum), and an intact record of NaN or out-of-range values (admitted,
// its values refused by validation).
void HostApplication::add_garbage(std::size_t k, core::GpsTime t, double t_s, HostRecords& records) {
  if (!scenario_fault_.garbage.contains(t_s)) return;
  RandomStream& rng = *garbage_rng_;
  for (int c = 1; c <= gnc::kChannels; ++c) {
    const auto channel = static_cast<gnc::Channel>(c);
    gnc::OutputRecords::Record r;
    r.size = gnc::record_size(channel);
    for (std::size_t i = 0; i < r.size; ++i) r.bytes[i] = static_cast<std::uint8_t>(rng.uniform() * 256.0);
    r.bytes[0] = gnc::kRecordMagic[0];
    r.bytes[1] = gnc::kRecordMagic[1];
    r.bytes[2] = static_cast<std::uint8_t>(c);
    r.bytes[3] = gnc::kRecordVersion;
    r.bytes[4] = static_cast<std::uint8_t>(r.size);
    r.bytes[5] = static_cast<std::uint8_t>(r.size >> 8);
    records.forward(r);
  }
  HostRecords::Sequences& sequence = craft_[k].sequence;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  records.add(sequence, gnc::TimeAtTone{t, Eigen::Quaterniond(nan, 0.0, 0.0, 0.0)});
  gnc::NavigationSolution navigation;
  navigation.t = t;
  navigation.chief_gcrf.r = Eigen::Vector3d::Constant(nan);
  records.add(sequence, navigation);
  records.add(sequence, GroundCommand{t, GroundCommand::Kind::kStartScience, -5});
  records.add(sequence, gnc::PropulsionTelemetry{t, Eigen::Vector3d::Zero(), nan, true});
  gnc::GpsMessage gps;
  gps.t = gps.epoch.t = t;
  gps.epoch.channel_count = 1;
  gps.epoch.channels[0].prn = 7;
  gps.epoch.channels[0].pseudorange_m = nan;
  records.add(sequence, gps);
  records.add(sequence, gnc::LaserRange{t, nan});
}

core::Result<bool> HostApplication::step_components(core::GpsTime t, double t_s, const std::array<bool, 2>& stepped,
                                                    std::array<HostRecords, 2>& records,
                                                    std::array<std::vector<float>, 2>& step_us) {
  const std::array<std::span<const gnc::RecordView>, 2> inputs{records[0].views(), records[1].views()};
  std::array<float, 2> us{};
  if (auto ok = software_.step(t, stepped, inputs, us); !ok) return ok.error();
  for (std::size_t k = 0; k < 2; ++k) {
    if (!stepped[k]) continue;
    step_us[k].push_back(us[k]);
    const Mode before = craft_[k].out.mode;
    read_outputs(k, software_.outputs(k), t_s);
    const Mode after = craft_[k].out.mode;
    if (after != before) recorder_->event(t_s, craft_[k].name, "mode", fmt::format("{} -> {}", to_string(before), to_string(after)));
  }
  return true;
}

void HostApplication::read_outputs(std::size_t k, const gnc::OutputRecords& out, double t_s) {
  HostedComponent& c = craft_[k];
  gnc::GncOutputs decoded;
  gnc::RecordHeader header;
  if (gnc::decode(out.telemetry.view(), decoded.telemetry, header) != gnc::RecordStatus::kAccepted) {
    recorder_->event(t_s, c.name, "rejected_message", "the component's telemetry record does not decode");
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
    else recorder_->event(t_s, c.name, "rejected_message", fmt::format("the component's {} record does not decode", name));
  };
  optional_output(out.maneuver, decoded.maneuver, "maneuver");
  optional_output(out.observation, decoded.observation, "observation");
  optional_output(out.navigation, decoded.navigation, "navigation");
  c.crosslink_out = out.crosslink;
  c.out = decoded;
}

// kFdirPolicy's triggers on the active spacecraft's outputs: a passive-safety violation (once per
// violation), GNC incapable for its persistence (GncIncapablePersistence) while the other is capable (and not in a bus
// safe mode, whose last outputs are stale).
void HostApplication::apply_fdir(std::size_t k, core::GpsTime t, double t_s) {
  HostedComponent& v = craft_[k];
  const HostedComponent& other = craft_[1 - k];
  if (!v.out.gnc_incapable) v.incapable.ever_capable = true;  // passive too: it may become the active one
  if (!v.out.telemetry.active) return;
  const core::GpsTime next = t + step_s_;
  if (v.out.passive_safety_violated && !v.violation_reported) {
    v.violation_reported = true;
    ++safety_violations_;
    recorder_->event(t_s, v.name, "safety_violation",
                     fmt::format("passive-safety margin {:.3f} m below epsilon; host commands escape", v.out.telemetry.safety_margin_m));
    respond(FdirTrigger::kSafetyViolation, k, next, t_s, v.name);
  }
  if (!v.out.passive_safety_violated) v.violation_reported = false;
  if (v.incapable.due(v.out.gnc_incapable, t_s) && !other.out.gnc_incapable && !in_safe_mode(1 - k, t_s)) {
    v.incapable = GncIncapablePersistence{.since_s = -1.0, .ever_capable = v.incapable.ever_capable};
    respond(FdirTrigger::kGncIncapable, k, next, t_s, fmt::format("{} GNC incapable", v.name));
  }
}

bool GncIncapablePersistence::due(bool incapable, double t_s) {
  if (!incapable) {
    since_s = -1.0;
    ever_capable = true;
    return false;
  }
  if (since_s < 0.0) since_s = t_s;
  return t_s - since_s >= (ever_capable ? kAfterCapable_s : kBeforeCapable_s);
}

void HostApplication::respond(FdirTrigger trigger, std::size_t victim, core::GpsTime deliver_at, double t_s, std::string_view what) {
  const FdirResponse response = fdir_response(trigger, craft_[victim].out.mode);
  const std::size_t other = 1 - victim;
  switch (response) {
    case FdirResponse::kEscape:
      command(victim, GroundCommand::Kind::kEscape, deliver_at);
      return;  // the violation's own event says so
    case FdirResponse::kTransferToStandby:
      command(victim, GroundCommand::Kind::kTransferToStandby, deliver_at);
      break;
    case FdirResponse::kRoleSwitch:
    case FdirResponse::kRoleSwitchThenStandby:
      command(victim, GroundCommand::Kind::kMakePassive, deliver_at);
      command(other, GroundCommand::Kind::kMakeActive, deliver_at);
      if (response == FdirResponse::kRoleSwitchThenStandby) {
        craft_[other].command_after = GroundCommand{deliver_at + step_s_, GroundCommand::Kind::kTransferToStandby, 0};
      }
      break;
  }
  recorder_->event(t_s, "sim", "fdir", fmt::format("{}: {}", what, response_text(response)));
}

}  // namespace visors::sim
