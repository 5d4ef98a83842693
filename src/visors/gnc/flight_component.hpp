#pragma once
// The GNC flight component of one spacecraft (docs/architecture.md#the-flight-component;
// Guffanti et al., AAS 23-149, 2023, sec. 4): typed inputs in, typed outputs out, one step per
// call, driven by the time tags it is given.
//
// Mode manager (the same paper, sec. 3): manual -> standby (command) -> transfer_to_science
// (command) -> science (N observation attempts) -> transfer_to_standby (autonomous) -> standby;
// escape on the host application's FDIR command (raised by this component's passive-safety
// check), exiting to manual once the escape pieces are fired. Only the ACTIVE spacecraft plans and
// fires; the passive one follows the active one's mode and observation schedule over the
// crosslink, and runs its own passive-safety check.
//
// Control stack per mode (active spacecraft):
//  - standby: once per check period, if a|de - de_t| > deadband or a|dlambda - dlambda_t| >
//    threshold, a closed-form plan back to the standby ROE over plan_orbits;
//  - transfer: guidance waypoints (control::transfer_waypoints) flown as closed-form legs of
//    leg_orbits each (two normal burns per leg), each leg planned from the current estimate and
//    aimed off by the estimated differential drag's drift over the leg (as the standby plans);
//  - science, per observation (observation_schedule.hpp: exact aligned target at mid-window):
//    the stochastic MPC (reachable-set planner) every mpc_period_s towards the aligned ROE carried
//    back to the start of the fine-control window; inside the window the least-squares planner at
//    the fixed burn times still ahead, replanned every least_squares_period_s, and for the last
//    burn a weighted solve of the position and velocity errors at alignment; both aim off by the
//    drift the estimated differential drag (differential_drag_estimator.hpp) still causes; then
//    the slew, the 10 s observation and the next one;
//  - escape: safety::plan_escape, as soon as allowed.
// Every plan goes through the maneuver buffer (ManeuverQueue).
//
// Robustness: every input is validated (messages.hpp) and a bad one counted and dropped; no
// exception leaves step(); a planner failure is counted, the previous plan kept, and repeated
// failures raise gnc_incapable. Memory: storage is sized at creation and the planners write into
// reserved outputs (plan_closed_form_into, plan_least_squares_into, StochasticMpc::step_into,
// transfer_waypoints_into, control::ImpulseBuffer), so no step allocates, replanning included
// (tests: RoutineStepAllocatesNothing, PlanningStepsAllocateNothing); only an error builds its
// message text.

#include <array>
#include <memory>
#include <optional>
#include <span>

#include "visors/astro/roe_stm.hpp"
#include "visors/control/closed_form_planner.hpp"
#include "visors/control/least_squares_planner.hpp"
#include "visors/control/stochastic_mpc.hpp"
#include "visors/core/result.hpp"
#include "visors/gnc/differential_drag_estimator.hpp"
#include "visors/gnc/gnc_config.hpp"
#include "visors/gnc/maneuver_queue.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/gnc/observation_schedule.hpp"
#include "visors/gnc/onboard_navigation.hpp"
#include "visors/gnc/relative_estimate.hpp"

namespace visors::gnc {

class FlightComponent {
 public:
  /// With `navigation`, the component navigates itself from its GPS, crosslink, propulsion and
  /// rangefinder channels (gnc/onboard_navigation.hpp) and the navigation channel is not used;
  /// without, it takes the navigation channel's solutions (ideal navigation).
  static core::Result<FlightComponent> create(const GncConfig& config,
                                              std::optional<OnboardNavigation> navigation = std::nullopt);

  /// One step at inputs.t (non-decreasing between calls; an earlier time is rejected as a whole
  /// and counted as a navigation rejection). Each input is validated (messages.hpp validate) and
  /// an invalid one counted by its channel (Telemetry::rejected) and not used.
  GncOutputs step(const GncInputs& inputs);
  /// The same with inputs that are valid at inputs.t already: what RecordInterface calls, which
  /// validates each record once, as it chooses the newest valid one of each channel.
  GncOutputs step_validated(const GncInputs& inputs);

  [[nodiscard]] Mode mode() const { return mode_; }
  [[nodiscard]] bool active() const { return active_; }
  [[nodiscard]] const GncConfig& config() const { return config_; }
  [[nodiscard]] const std::optional<RelativeEstimate>& estimate() const { return estimate_; }
  /// The on-board navigation, when the component has one.
  [[nodiscard]] const std::optional<OnboardNavigation>& navigation() const { return navigation_; }

 private:
  FlightComponent(const GncConfig& config, control::StochasticMpc mpc, std::optional<OnboardNavigation> navigation);

  /// `inputs` without those validation refuses (counted by channel).
  GncInputs admit(const GncInputs& inputs);
  void accept_inputs(const GncInputs& inputs, GncOutputs& out);
  void accept_attitude(const TimeAtTone& tone);
  /// The own GPS, rangefinder and propulsion inputs into the on-board navigation.
  void feed_navigation(const GncInputs& inputs);
  /// A navigation solution (the channel's, or the on-board navigation's) as the estimate;
  /// `measured` is the time of the measurements behind it.
  bool accept_solution(const NavigationSolution& solution, core::GpsTime measured);
  void apply_command(const GroundCommand& command);
  void follow_peer(const CrosslinkMessage& peer, GncOutputs& out);
  void enter(Mode mode);
  void check_safety();
  void run_control(GncOutputs& out);
  void run_standby();
  void run_transfer();
  void run_science(GncOutputs& out);
  void run_escape();
  void release_maneuver(GncOutputs& out);
  void fill_crosslink(GncOutputs& out) const;
  bool start_transfer(const astro::RelativeOrbitalElements& target);
  bool plan_leg();
  bool schedule_observation(GncOutputs& out);
  void science_fine_control();
  void science_mpc();
  void replan_last_burn(const astro::RelativeOrbitalElements& target, double t_burn, double to_aligned);
  /// Buffers `impulses` (times since the estimate) replacing what is queued; counts the plan or
  /// the failure.
  bool replace_plan(std::span<const control::Impulse> impulses);
  void planning_failed();
  double chief_period_s() const;
  /// The mean-ROE change at `horizon_s` s after the estimate that the estimated differential drag
  /// produces from the estimate on (midpoint quadrature of Phi Gamma a_T); zero until the
  /// estimator is valid.
  astro::RelativeOrbitalElements drag_drift(double horizon_s) const;
  double since(core::GpsTime t) const { return now_.seconds_since(t); }

  GncConfig config_;
  control::StochasticMpc mpc_;
  ManeuverQueue queue_;
  // Planner outputs with their capacity reserved at creation, so replanning allocates nothing.
  control::ManeuverPlan plan_;
  control::LeastSquaresPlan ls_plan_;
  control::MpcStep mpc_step_;
  std::array<control::Impulse, 1> single_{};
  Mode mode_ = Mode::kManual;
  bool active_ = true;
  double mass_kg_ = 0.0;
  core::GpsTime now_;
  bool started_ = false;
  Eigen::Quaterniond q_body_to_gcrf_ = Eigen::Quaterniond::Identity();
  bool has_attitude_ = false;
  core::GpsTime attitude_t_;
  // The attitude of the step before (an impulse's telemetry arrives the step after it).
  Eigen::Quaterniond q_previous_ = Eigen::Quaterniond::Identity();
  core::GpsTime previous_attitude_t_;
  std::optional<OnboardNavigation> navigation_;
  std::optional<RelativeEstimate> estimate_;
  core::GpsTime last_navigation_;
  // Safety.
  bool safety_checked_ = false;
  core::GpsTime last_safety_check_;
  double safety_margin_m_ = 0.0;
  bool safety_violated_ = false;
  // Standby.
  core::GpsTime last_standby_check_;
  bool standby_checked_ = false;
  // Transfer.
  std::vector<astro::RelativeOrbitalElements> waypoints_;
  std::size_t leg_ = 0;
  core::GpsTime leg_end_;
  bool leg_planned_ = false;
  // Science.
  /// The observation geometry of the campaign: config.science.geometry with the pole chosen at
  /// the start of the transfer to science (the configuration itself is never changed).
  control::ScienceGeometry geometry_;
  int observations_planned_ = 0;
  int observations_done_ = 0;
  std::optional<ScheduledObservation> observation_;
  core::GpsTime mpc_epoch_;
  /// Phi(t_aligned, t_handover)^-1: carries a mean-ROE change at the aligned time back to the
  /// MPC's target time (the free J2 motion over the fine-control window).
  astro::RoeStm window_stm_inverse_ = astro::RoeStm::Identity();
  core::GpsTime last_mpc_;
  bool mpc_started_ = false;
  bool ls_planned_ = false;  // a least-squares plan exists for the current observation
  core::GpsTime last_ls_;
  DifferentialDragEstimator drag_;
  // Escape.
  bool escape_planned_ = false;
  // Counters.
  Telemetry telemetry_;
  int consecutive_failures_ = 0;
};

}  // namespace visors::gnc
