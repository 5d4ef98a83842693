#include "visors/gnc/messages.hpp"

#include <cmath>

#include "visors/gnss/gps_measurement.hpp"

namespace visors::gnc {

namespace {

using core::Problem;

// How old an input may be and still be used [s]: the channel rates of
// Guffanti et al., AAS 23-149, 2023, Table 2, with margin (time at tone and GPS 2 s, navigation and
// rangefinder 5 s, crosslink 10 s for its 0.5 s delay plus drops, weekly commands one minute after
// their time tag, propulsion telemetry 120 s, over two maneuver spacings;
// docs/requirements.md#interfaces-and-rates).
constexpr double kMaxAgeTone = 2.0;
constexpr double kMaxAgeNavigation = 5.0;
constexpr double kMaxAgeCrosslink = 10.0;
constexpr double kMaxAgeCommand = 60.0;
constexpr double kMaxAgePropulsion = 120.0;
constexpr double kMaxAgeGps = 2.0;
constexpr double kMaxAgeLaser = 5.0;
constexpr double kMaxLaserRange = 1.0e4;  // [m], far beyond the 40 m formation
// Plausibility bounds of a spacecraft state in low Earth orbit.
constexpr double kMinRadius = 6.0e6;   // [m], below the Earth's surface
constexpr double kMaxRadius = 1.0e8;   // [m]
constexpr double kMaxSpeed = 2.0e4;    // [m/s]
constexpr double kMaxImpulseDv = 1.0;  // [m/s], far above one 2.2e-2 N s impulse
constexpr int kMaxObservations = 1000;

core::Status check_age(core::GpsTime t, core::GpsTime now, double max_age, const char* field) {
  const double age = static_cast<double>(now.nanoseconds() - t.nanoseconds()) * 1e-9;
  if (age < 0.0) return {Problem::kInTheFuture, field};
  if (age > max_age) return {Problem::kTooOld, field};
  return {};
}

core::Status check_state(const core::StateVector& x, const char* field) {
  if (!x.r.allFinite() || !x.v.allFinite()) return {Problem::kNotFinite, field};
  const double r = x.r.norm();
  if (r < kMinRadius || r > kMaxRadius) return {Problem::kOutOfRange, field};  // not in low Earth orbit
  if (x.v.norm() > kMaxSpeed) return {Problem::kOutOfRange, field};
  return {};
}

core::Status check_unit(const Eigen::Quaterniond& q, const char* field) {
  if (!q.coeffs().allFinite()) return {Problem::kNotFinite, field};
  if (std::abs(q.norm() - 1.0) > 1e-6) return {Problem::kNotUnit, field};
  return {};
}

// The crosslinked epoch's structure: 0..12 observations of PRNs 1..32, none repeated.
core::Status check_epoch(const CrosslinkEpoch& epoch) {
  if (epoch.count < 0 || epoch.count > gnss::kMaxGpsChannels) return {Problem::kOutOfRange, "crosslink.navigation.epoch.count"};
  for (int i = 0; i < epoch.count; ++i) {
    const int prn = epoch.observations[static_cast<std::size_t>(i)].prn;
    if (prn < 1 || prn > 32) return {Problem::kOutOfRange, "crosslink.navigation.epoch.observations.prn"};
    for (int j = 0; j < i; ++j) {
      if (epoch.observations[static_cast<std::size_t>(j)].prn == prn) {
        return {Problem::kRepeated, "crosslink.navigation.epoch.observations.prn"};
      }
    }
  }
  return {};
}

core::Status check_range(double range_m, const char* field) {
  if (!std::isfinite(range_m) || range_m <= 0.0 || range_m > kMaxLaserRange) return {Problem::kOutOfRange, field};
  return {};
}

core::Status check_navigation(const CrosslinkNavigation& n, core::GpsTime sent) {
  if (n.has_epoch) {
    if (const auto ok = check_epoch(n.epoch); !ok) return ok;
    if (n.epoch.t > sent) return {Problem::kInconsistent, "crosslink.navigation.epoch.t"};  // after the message
    if (const auto ok = check_unit(n.q_body_to_gcrf, "crosslink.navigation.q_body_to_gcrf"); !ok) return ok;
  }
  if (n.impulse_count < 0 || n.impulse_count > kCrosslinkImpulses) return {Problem::kOutOfRange, "crosslink.navigation.impulse_count"};
  for (int k = 0; k < n.impulse_count; ++k) {
    const ExecutedImpulse& i = n.impulses[static_cast<std::size_t>(k)];
    if (!i.dv_gcrf_mps.allFinite() || i.dv_gcrf_mps.norm() > kMaxImpulseDv || i.t > sent) {
      return {Problem::kOutOfRange, "crosslink.navigation.impulses"};  // finite, below 1 m/s, not after the message
    }
  }
  if (n.has_range) return check_range(n.range.range_m, "crosslink.navigation.range.range_m");
  return {};
}

}  // namespace

std::string_view to_string(Spacecraft spacecraft) { return spacecraft == Spacecraft::kDsc ? "dsc" : "osc"; }

std::string_view to_string(GroundCommand::Kind kind) {
  switch (kind) {
    case GroundCommand::Kind::kToManual: return "to_manual";
    case GroundCommand::Kind::kToStandby: return "to_standby";
    case GroundCommand::Kind::kStartScience: return "start_science";
    case GroundCommand::Kind::kTransferToStandby: return "transfer_to_standby";
    case GroundCommand::Kind::kEscape: return "escape";
    case GroundCommand::Kind::kMakeActive: return "make_active";
    case GroundCommand::Kind::kMakePassive: return "make_passive";
  }
  return "unknown";
}

core::Status validate(const TimeAtTone& message, core::GpsTime now) {
  if (const auto ok = check_age(message.t, now, kMaxAgeTone, "time_at_tone.t"); !ok) return ok;
  return check_unit(message.q_body_to_gcrf, "time_at_tone.q_body_to_gcrf");
}

core::Status validate(const NavigationSolution& message, core::GpsTime now) {
  if (const auto ok = check_age(message.t, now, kMaxAgeNavigation, "navigation.t"); !ok) return ok;
  if (const auto ok = check_state(message.chief_gcrf, "navigation.chief_gcrf"); !ok) return ok;
  if (const auto ok = check_state(message.deputy_gcrf, "navigation.deputy_gcrf"); !ok) return ok;
  const auto& p = message.relative_covariance_rtn;
  if (!p.allFinite()) return {Problem::kNotFinite, "navigation.relative_covariance_rtn"};
  if ((p - p.transpose()).cwiseAbs().maxCoeff() > 1e-9 * std::max(1e-300, p.cwiseAbs().maxCoeff())) {
    return {Problem::kNotSymmetric, "navigation.relative_covariance_rtn"};
  }
  if ((p.diagonal().array() < 0.0).any()) {
    return {Problem::kOutOfRange, "navigation.relative_covariance_rtn"};  // a negative variance
  }
  return {};
}

core::Status validate(const CrosslinkMessage& message, core::GpsTime now) {
  if (const auto ok = check_age(message.t, now, kMaxAgeCrosslink, "crosslink.t"); !ok) return ok;
  if (static_cast<int>(message.sender) > 1) return {Problem::kUnknown, "crosslink.sender"};
  if (static_cast<int>(message.mode) >= kModeCount) return {Problem::kUnknown, "crosslink.mode"};
  if (message.observations_done < 0 || message.observations_done > kMaxObservations) {
    return {Problem::kOutOfRange, "crosslink.observations_done"};
  }
  if (message.observations_planned < 0 || message.observations_planned > kMaxObservations) {
    return {Problem::kOutOfRange, "crosslink.observations_planned"};
  }
  if (message.has_observation &&
      !(message.slew_start <= message.observation_start && message.observation_start <= message.observation_end)) {
    return {Problem::kInconsistent, "crosslink.observation_start"};  // slew_start <= start <= end
  }
  return check_navigation(message.navigation, message.t);
}

core::Status validate(const GroundCommand& message, core::GpsTime now) {
  if (const auto ok = check_age(message.t, now, kMaxAgeCommand, "command.t"); !ok) return ok;
  if (static_cast<int>(message.kind) > static_cast<int>(GroundCommand::Kind::kMakePassive)) {
    return {Problem::kUnknown, "command.kind"};
  }
  if (message.kind == GroundCommand::Kind::kStartScience &&
      (message.observations < 1 || message.observations > kMaxObservations)) {
    return {Problem::kOutOfRange, "command.observations"};  // 1..1000
  }
  return {};
}

core::Status validate(const PropulsionTelemetry& message, core::GpsTime now) {
  if (const auto ok = check_age(message.t, now, kMaxAgePropulsion, "propulsion.t"); !ok) return ok;
  if (!message.dv_body_mps.allFinite() || message.dv_body_mps.norm() > kMaxImpulseDv) {
    return {Problem::kOutOfRange, "propulsion.dv_body_mps"};  // finite and below 1 m/s
  }
  if (!(message.mass_kg > 0.0) || !std::isfinite(message.mass_kg)) return {Problem::kOutOfRange, "propulsion.mass_kg"};
  return {};
}

core::Status validate(const GpsMessage& message, core::GpsTime now) {
  if (const auto ok = check_age(message.t, now, kMaxAgeGps, "gps.t"); !ok) return ok;
  if (message.epoch.t != message.t) return {Problem::kInconsistent, "gps.epoch.t"};
  if (const core::Status epoch = gnss::validate(message.epoch); !epoch) return {epoch.problem(), "gps.epoch"};
  return {};
}

core::Status validate(const LaserRange& message, core::GpsTime now) {
  if (const auto ok = check_age(message.t, now, kMaxAgeLaser, "laser_range.t"); !ok) return ok;
  return check_range(message.range_m, "laser_range.range_m");
}

}  // namespace visors::gnc
