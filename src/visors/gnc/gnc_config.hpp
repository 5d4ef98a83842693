#pragma once
// Configuration of the flight component (the configuration channel): every threshold, horizon and
// period is here with its default and why. Defaults follow Guffanti et al., AAS 23-149, 2023
// (below "the paper": its GNC algorithms table, Table 3, and test-case table, Table 5) where it
// gives a number; the others are stated as this project's. Each default with its source:
// docs/requirements.md#guidance-and-control-defaults.

#include <array>

#include "visors/control/guidance.hpp"
#include "visors/control/least_squares_planner.hpp"
#include "visors/control/maneuver_buffer.hpp"
#include "visors/control/stochastic_mpc.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/status.hpp"
#include "visors/gnc/differential_drag_estimator.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/safety/escape_maneuver.hpp"
#include "visors/safety/passive_safety_settings.hpp"

namespace visors::gnc {

struct StandbyKeepingSettings {
  /// How often the standby orbit is checked (paper: once per orbit) [chief orbits].
  double check_period_orbits = 1.0;
  /// Deadband on a |de - de_target| (paper: a de_dbd; value ours: 1 % of the 200 m standby
  /// separation, so the RN separation stays within 2 m of the design) [m].
  double de_deadband_m = 2.0;
  /// Threshold on a |dlambda - dlambda_target| (paper: a dlambda_thr, driven by differential
  /// drag; value ours: a tenth of the standby separation) [m].
  double dlambda_threshold_m = 20.0;
  /// Horizon of a station-keeping plan (closed form needs >= 1.5 orbits) [chief orbits].
  double plan_orbits = 2.0;
  /// Aim each plan off by the drift the estimated differential drag causes over its horizon
  /// (the closed-form planner's model is J2 only).
  bool drag_compensation = true;
};

struct TransferSettings {
  control::TransferSettings waypoints;
  /// Duration of one reconfiguration leg (paper: 1.5-orbit steps; 1.6 leaves the closed-form
  /// planner its 1.5-orbit window after the burn latency and the end margin) [chief orbits].
  double leg_orbits = 1.6;
  /// Normal burns per leg: 2 halves each normal impulse (one orbit apart), so the buffer can
  /// spread it within its piece limit (a 200 m -> 120 m delta-i step needs ~90 mm/s).
  int normal_burns = 2;
  /// The last allowed burn of a leg is this long before the leg end [s].
  double end_margin_s = 60.0;
  /// Aim each leg off by the drift the estimated differential drag causes over it. The
  /// closed-form planner's model is J2 only; at 500 km and high solar activity a 1e-6 m/s^2
  /// differential acceleration moves the along-track separation by 1.5 a_T t^2 ~ 100 m over a
  /// 1.6-orbit leg, which the first science approach then has to undo.
  bool drag_compensation = true;
  /// Capacity of the waypoint list, reserved at creation (1..kMaxTransferWaypoints): a transfer
  /// needing more legs is a planning failure (a degenerate geometry; a transfer of the default
  /// campaign takes 8 legs).
  int max_waypoints = 64;
};
inline constexpr int kMaxTransferWaypoints = 1024;

/// The MPC's execution-error model set to the simulated actuator (magnitude 5 % 1-sigma, the lower
/// bound of the paper's propulsion table, Table 1(b); floor one impulse quantum, 6e-5 N s / 10.6 kg
/// = 6 um/s), so the Mahalanobis test replans when the error grows beyond what the thrusters
/// explain.
inline control::StochasticMpcSettings science_mpc_defaults() {
  control::StochasticMpcSettings settings;
  settings.execution_sigma_fraction = 0.05;
  settings.execution_sigma_floor_mps = 6e-6;
  return settings;
}

struct ScienceSettings {
  control::ScienceGeometry geometry;
  /// Choose the observation pole at the start of each campaign (choose_north_pole) instead of
  /// geometry.north.
  bool choose_pole = true;
  /// Fine control window before each observation: least squares at fixed times (paper: last
  /// 10-15 min) [s].
  double least_squares_window_s = 900.0;
  /// Burn times of the least-squares planner, seconds before the observation, decreasing: the
  /// first `least_squares_burns` entries are used (1..kMaxLeastSquaresBurns). A burn whose pieces
  /// could not end one plenum refill before the slew starts is skipped, and so is one inside the
  /// planning latency (the first, at the window's start, usually is).
  /// Six burns 150 s apart: each replanning corrects the execution error of the burn before, so
  /// the error reaching the observation shrinks as (magnitude error x 150 s / lead time) per burn,
  /// and the last burn only trims (the choice and its measurement: docs/decisions.md, "Six
  /// fine-control burns").
  std::array<double, control::kMaxLeastSquaresBurns> least_squares_burns_before_s{900.0, 750.0, 600.0, 450.0, 300.0, 150.0};
  int least_squares_burns = 6;
  control::LeastSquaresSettings least_squares;
  /// Weight of the relative velocity against the position in the last burn's solve: the ratio of
  /// the requirements, 18 mm / 0.2 mm/s [s].
  double last_burn_velocity_weight_s = 90.0;
  /// The least-squares plan is recomputed this often on the newest estimate, so differential drag
  /// and execution errors are corrected up to the last burn (paper: every 45 s) [s].
  double least_squares_period_s = 45.0;
  /// The reachable-set MPC runs on navigation updates this far apart (paper: every 5 min) [s].
  double mpc_period_s = 300.0;
  control::StochasticMpcSettings mpc = science_mpc_defaults();
  /// The first observation after entering science is at least this far ahead, so the MPC has
  /// a horizon (0.5 orbit) [s].
  double min_lead_s = 2900.0;
  double observation_duration_s = 10.0;  // [s] (requirement: 10 s windows)
  double slew_rate_radps = 1.5 * core::kPi / 180.0;  // [rad/s] (paper: 1.5 deg/s)
  double slew_settle_s = 30.0;                       // settling after the slew [s] (ours)
  /// Midpoint-rule nodes of the differential-drag drift to the aligned time (FlightComponent::
  /// drag_drift; 1..kMaxDragDriftNodes). 24 nodes over the <= 900 s window make the quadrature
  /// error negligible against the drag estimate's own.
  int drag_drift_nodes = 24;
  /// Added to the predicted slew angle when timing the slew command [rad]. The slew from the
  /// nominal attitude (+Z at zenith, +X towards the Sun's projection on the horizontal plane) to
  /// the observation attitude (+X at the Sun) is a rotation by the Sun's elevation, near zero at
  /// the TN-plane alignment.
  double slew_margin_rad = 5.0 * core::kPi / 180.0;
};
inline constexpr int kMaxDragDriftNodes = 1000;

struct GncConfig {
  Spacecraft self = Spacecraft::kOsc;
  bool active = true;        // initial role: the active spacecraft maneuvers
  double mass_kg = 10.62;    // own wet mass at start (updated by propulsion telemetry) [kg]
  core::EarthGravityConstants gravity;
  control::StandbyOrbit standby;
  StandbyKeepingSettings standby_keeping;
  TransferSettings transfer;
  DifferentialDragSettings drag;
  ScienceSettings science;
  safety::PassiveSafetySettings safety;
  safety::EscapeSettings escape;
  control::BufferSettings buffer;
  /// A new plan's first burn is no earlier than this after the step that planned it [s].
  double burn_latency_s = 10.0;
  /// Consecutive planning failures after which "GNC incapable" is raised.
  int max_planning_failures = 3;
  /// Without a navigation solution for this long the component stops planning and reports
  /// itself GNC incapable [s].
  double max_estimate_age_s = 10.0;
  /// Capacity of the maneuver queue in thruster pieces, reserved at creation
  /// (1..kMaxManeuverQueuePieces): a plan that would need more is refused (planning failure).
  int maneuver_queue_capacity = 4096;
};
inline constexpr int kMaxManeuverQueuePieces = 1 << 20;

/// Checks every field (names as in the struct, e.g. "standby_keeping.de_deadband_m").
core::Status validate(const GncConfig& config);

}  // namespace visors::gnc
