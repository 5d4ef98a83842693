#pragma once
// The flight component's channels as typed records (docs/architecture.md#channels;
// Guffanti et al., AAS 23-149, 2023, sec. 4.1 and its inputs-and-outputs table, Table 2). Inputs
// arrive at any time or not at all; each one is validated (validate_* below) and a bad record is
// rejected, counted in telemetry, and never used. Outputs are produced by every step.
//
// Relative states follow docs/conventions.md: deputy (OSC) minus chief (DSC), chief RTN.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "visors/core/status.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/gnc/gnc_mode.hpp"
#include "visors/gnc/input_rejections.hpp"
#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/gps_measurement.hpp"

namespace visors::gnc {

enum class Spacecraft : std::uint8_t { kDsc, kOsc };
std::string_view to_string(Spacecraft spacecraft);

// ---- Inputs.

/// Time at tone with the attitude solution (1 Hz).
struct TimeAtTone {
  core::GpsTime t;
  Eigen::Quaterniond q_body_to_gcrf = Eigen::Quaterniond::Identity();  // scalar first, Hamilton
};

/// GPS message (1 Hz): the own receiver's epoch (L1 C/A code and carrier phase per tracked
/// satellite, at most gnss::kMaxGpsChannels) and at most one broadcast record it decoded since the
/// previous message (a receiver decodes a satellite's subframes in 30 s; a whole data set
/// arrives over a few dozen messages).
struct GpsMessage {
  core::GpsTime t;                   // the receiver's time tag (= epoch.t)
  gnss::GpsMeasurementEpoch epoch;
  bool has_ephemeris = false;
  gnss::BroadcastEphemeris ephemeris;
};

/// Laser rangefinder measurement (OSC, every 2 s during observations).
struct LaserRange {
  core::GpsTime t;
  double range_m = 0.0;  // from the OSC's rangefinder to the DSC's target point [m]
};

/// Navigation solution (1 Hz) from outside the component: absolute states of both spacecraft and
/// the covariance of the relative state (the simulator's ideal navigation, `[navigation] mode =
/// "ideal"`; with on-board GPS navigation the component makes its own, gnc/onboard_navigation.hpp).
struct NavigationSolution {
  core::GpsTime t;
  core::StateVector chief_gcrf;   // DSC [m, m/s]
  core::StateVector deputy_gcrf;  // OSC [m, m/s]
  /// Covariance of [dr_rtn; dv_rtn] of the deputy relative to the chief [m^2, m^2/s^2].
  Eigen::Matrix<double, 6, 6> relative_covariance_rtn = Eigen::Matrix<double, 6, 6>::Identity() * 1e-4;
};

/// Ground commands (weekly); FDIR responses of the host application use the same record.
struct GroundCommand {
  enum class Kind : std::uint8_t {
    kToManual,            // stop autonomous control
    kToStandby,           // from manual: acquire / keep the standby orbit
    kStartScience,        // from standby: transfer to science, then `observations` attempts
    kTransferToStandby,   // FDIR: abort science or transfer, go back to standby
    kEscape,              // FDIR: plan and execute the escape maneuver, then manual
    kMakeActive,          // role switch: this spacecraft maneuvers
    kMakePassive,         // role switch: this spacecraft does not maneuver
  };
  core::GpsTime t;
  Kind kind = Kind::kToManual;
  int observations = 10;  // start_science only
};
std::string_view to_string(GroundCommand::Kind kind);

/// Propulsion telemetry after each impulse.
struct PropulsionTelemetry {
  core::GpsTime t;
  Eigen::Vector3d dv_body_mps = Eigen::Vector3d::Zero();  // as executed (commanded, quantised) [m/s]
  double mass_kg = 0.0;                                   // after the impulse [kg]
  bool executed = false;                                  // false: the command was refused
};

/// An impulse a spacecraft executed, as its component knows it: the commanded (quantised) dv of its
/// propulsion telemetry, in GCRF through the attitude at that time.
struct ExecutedImpulse {
  core::GpsTime t;
  Eigen::Vector3d dv_gcrf_mps = Eigen::Vector3d::Zero();  // [m/s]
};
inline constexpr int kCrosslinkImpulses = 2;

/// One satellite of the sender's receiver epoch: L1 C/A code and carrier phase with the
/// receiver's two loss-of-lock bits (RINEX LLI bits 0 and 1).
struct CrosslinkObservation {
  int prn = 0;                // 1..32
  double code_m = 0.0;        // pseudorange [m]
  double phase_cycles = 0.0;  // carrier phase [cycles] (RINEX sign: grows with the range)
  bool loss_of_lock = false;  // a slip may have occurred since the previous epoch
  bool half_cycle = false;    // the phase may be off by half a cycle, until resolved
};

/// The sender's receiver epoch as the crosslink carries it (the filter's own form is the
/// navigation's: gnc/onboard_navigation.hpp converts at its edge).
struct CrosslinkEpoch {
  core::GpsTime t;  // the receiver's time tag
  int count = 0;    // observations, 0..gnss::kMaxGpsChannels
  std::array<CrosslinkObservation, gnss::kMaxGpsChannels> observations{};
};

/// The navigation part of the crosslink: what the other spacecraft's filter needs of the sender.
struct CrosslinkNavigation {
  bool has_epoch = false;
  CrosslinkEpoch epoch;  // the sender's receiver epoch of its step
  Eigen::Quaterniond q_body_to_gcrf = Eigen::Quaterniond::Identity();  // the sender's attitude at epoch.t
  /// The sender's last executed impulses, newest first, repeated in every message, so that one
  /// lost message loses none (impulses are at least 46.5 s apart).
  int impulse_count = 0;
  std::array<ExecutedImpulse, kCrosslinkImpulses> impulses{};
  bool has_range = false;  // the OSC's newest rangefinder measurement
  LaserRange range;
};

/// Crosslink (1 Hz, delayed): what the other spacecraft's component tells this one.
struct CrosslinkMessage {
  core::GpsTime t;  // when it was sent
  Spacecraft sender = Spacecraft::kDsc;
  Mode mode = Mode::kManual;
  bool sender_active = false;
  int observations_done = 0;
  int observations_planned = 0;
  bool has_observation = false;  // the next observation below is scheduled
  int observation_index = 0;
  core::GpsTime slew_start, observation_start, observation_end;
  CrosslinkNavigation navigation;
};

/// Everything that arrived for one step; absent channels are empty.
struct GncInputs {
  core::GpsTime t;
  std::optional<TimeAtTone> time_at_tone;
  std::optional<GpsMessage> gps;
  std::optional<LaserRange> laser_range;
  std::optional<NavigationSolution> navigation;
  std::optional<CrosslinkMessage> crosslink;
  std::optional<GroundCommand> command;
  std::optional<PropulsionTelemetry> propulsion;
};

// ---- Outputs.

struct ManeuverCommand {
  core::GpsTime t;
  Eigen::Vector3d dv_body_mps = Eigen::Vector3d::Zero();  // for the thrusters [m/s]
  Eigen::Vector3d dv_rtn_mps = Eigen::Vector3d::Zero();   // the same impulse, own spacecraft's view of the chief RTN [m/s]
};

struct ObservationCommand {
  core::GpsTime t;  // when issued
  int index = 0;    // 1-based attempt number
  core::GpsTime slew_start, start, end;
};

struct Telemetry {
  core::GpsTime t;
  Mode mode = Mode::kManual;
  bool active = false;
  bool estimate_valid = false;
  // The step's discrete outputs (GncOutputs), so that the telemetry record carries them.
  bool star_tracker_power = false, lrf_power = false, gnc_incapable = false, passive_safety_violated = false;
  Eigen::Matrix<double, 6, 1> roe_mean_m = Eigen::Matrix<double, 6, 1>::Zero();  // a * mean ROE [m]
  bool safety_checked = false;       // a check has been made
  double safety_margin_m = 0.0;      // last check: min separation - q sigma [m]
  int observations_done = 0;
  /// a * mean ROE the science control aims at for the next observation [m] (zero outside science).
  Eigen::Matrix<double, 6, 1> roe_target_m = Eigen::Matrix<double, 6, 1>::Zero();
  int pending_pieces = 0;            // buffered impulses not yet commanded
  std::int64_t plans = 0;            // planner calls that produced a plan
  std::int64_t planning_failures = 0;
  InputRejections rejected;  // every input refused (its bytes, its values, or unusable), by reason and channel
  // On-board navigation (mode "cdgps"): its solution is in use, its last update was fixed, when.
  bool navigation_valid = false, navigation_fixed = false;
  core::GpsTime navigation_update;
  /// The differential along-track acceleration the planners assume (deputy minus chief), and
  /// whether its estimator is valid (differential_drag_estimator.hpp) [m/s^2].
  bool drag_valid = false;
  double differential_drag_mps2 = 0.0;
};

/// What the on-board navigation did so far (telemetry).
inline constexpr int kEphemerisStatuses = 6;  // gnss::EphemerisStore::AcceptStatus, kStored .. kInconsistent
struct NavigationCounters {
  std::int64_t epochs_joint = 0;      // processed with both receivers
  std::int64_t epochs_alone = 0;      // processed with the own receiver only
  std::int64_t epochs_refused = 0;    // refused by the filter (its report's reason)
  std::int64_t epochs_fixed = 0;      // updates with a fixed solution
  std::int64_t wrong_fixes_refused = 0;
  std::int64_t impulses_applied = 0, impulses_late = 0;
  std::int64_t laser_used = 0, laser_rejected = 0;
  std::int64_t clock_jumps = 0;       // receiver clock jumps taken into the clock states
  std::array<std::int64_t, kEphemerisStatuses> ephemerides{};  // broadcast records by acceptance status
};

/// At most this many double differences in a navigation telemetry record: the component's epochs
/// hold at most kMaxGpsChannels observations per receiver (its GPS message and the crosslink
/// carry no more), so an epoch has at most that many common satellites, one the reference.
inline constexpr int kTelemetryDoubleDifferences = gnss::kMaxGpsChannels - 1;

/// One fixed double difference of an epoch: satellite `prn` against the epoch's reference,
/// SD(prn) - SD(reference), each SD the L1 ambiguity OSC minus DSC [cycles].
struct FixedDoubleDifference {
  int prn = 0;
  /// The fixed integer of a full fix (nav::CdgpsEpochReport::dd_integer_cycles); 0 after a
  /// partial fix, which fixes integer combinations, not single double differences.
  std::int64_t integer_cycles = 0;
  /// The double difference of the fixed solution (x_fixed): the integer after a full fix (to
  /// rounding), the value the fixed combinations imply after a partial one; NaN when the filter
  /// holds no ambiguity slot for one of the two satellites.
  double fixed_cycles = 0.0;
};

/// One integer combination a partial fix constrains:
///   sum over j < dd_count of dd_coefficients[j] DD_j = integer_cycles [cycles],
/// DD_j the double difference of NavigationTelemetry::dd[j] (nav::CdgpsEpochReport::fixed_combinations).
struct FixedCombination {
  std::array<std::int32_t, kTelemetryDoubleDifferences> dd_coefficients{};  // 0 beyond dd_count
  std::int64_t integer_cycles = 0;
};

/// Navigation telemetry (1 Hz, on-board navigation only): what a ground team needs to score the
/// navigation against its own truth or reference (the solution in use, its phase-centre and
/// empirical-acceleration estimates, the last epoch's fix and its integers, the counters), so
/// that nothing outside the component reads its state. Frames per docs/conventions.md.
struct NavigationTelemetry {
  core::GpsTime t;                 // the solution's time (the step's)
  bool has_solution = false;       // the filter has started: a solution exists, valid or not
  bool valid = false;              // the solution meets the validity sigmas: control and safety use it
  bool fixed = false;              // it comes from a fixed update (the fixed solution), else float
  core::StateVector dsc_gcrf, osc_gcrf;  // estimated centres of mass at t, GCRF [m, m/s]
  /// Estimated errors of the antenna phase-centre offsets, body frame [m], of the solution in use.
  Eigen::Vector3d p_dsc_body_m = Eigen::Vector3d::Zero(), p_osc_body_m = Eigen::Vector3d::Zero();
  /// Estimated empirical accelerations, each in its own spacecraft's RTN frame [m/s^2].
  Eigen::Vector3d empirical_dsc_rtn_mps2 = Eigen::Vector3d::Zero(), empirical_osc_rtn_mps2 = Eigen::Vector3d::Zero();
  /// 1-sigma of the relative position (OSC minus DSC), chief RTN [m]: root of the covariance's diagonal.
  Eigen::Vector3d relative_sigma_rtn_m = Eigen::Vector3d::Zero();
  /// The time tag of the last epoch the filter updated with (or of its cold start); the fields
  /// below are of the last epoch it processed: that one, unless it refused a later one (then no
  /// fix, and epochs_refused counts it).
  core::GpsTime update_t;
  bool fix_applied = false;        // a fix (full or partial) was applied at that epoch
  bool full_fix = false;           // every double difference fixed: integer_cycles hold the integers
  int dd_reference_prn = 0;        // the double differences' reference satellite (0 without a fix)
  int dd_count = 0;                // double differences of the fix, 0..kTelemetryDoubleDifferences
  std::array<FixedDoubleDifference, kTelemetryDoubleDifferences> dd{};
  /// The integer combinations of a partial fix (0 otherwise, and when the epoch had more double
  /// differences than the record holds), 0..dd_count.
  int combination_count = 0;
  std::array<FixedCombination, kTelemetryDoubleDifferences> combinations{};
  NavigationCounters counters;
};

struct GncOutputs {
  std::optional<ManeuverCommand> maneuver;
  std::optional<ObservationCommand> observation;  // issued once per attempt, when scheduled
  std::optional<CrosslinkMessage> crosslink;
  Mode mode = Mode::kManual;
  bool star_tracker_power = false;  // science mode
  bool lrf_power = false;           // science mode
  bool gnc_incapable = false;       // no valid estimate, or planning keeps failing
  bool passive_safety_violated = false;
  Telemetry telemetry;
  std::optional<NavigationTelemetry> navigation;  // every step, with on-board navigation
};

// ---- Validation: ok, or the problem and the field by its name (core::Status: no allocation, so a
// refused record costs nothing but its count); times must be within their channel's age of the step.

core::Status validate(const TimeAtTone& message, core::GpsTime now);
core::Status validate(const NavigationSolution& message, core::GpsTime now);
core::Status validate(const CrosslinkMessage& message, core::GpsTime now);
core::Status validate(const GroundCommand& message, core::GpsTime now);
core::Status validate(const PropulsionTelemetry& message, core::GpsTime now);
core::Status validate(const GpsMessage& message, core::GpsTime now);
core::Status validate(const LaserRange& message, core::GpsTime now);

}  // namespace visors::gnc
