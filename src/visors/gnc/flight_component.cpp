#include "visors/gnc/flight_component.hpp"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/roe_rtn_map.hpp"
#include "visors/astro/roe_stm.hpp"
#include "visors/control/closed_form_planner.hpp"
#include "visors/control/impulse_effect.hpp"
#include "visors/control/least_squares_planner.hpp"
#include "visors/safety/escape_maneuver.hpp"
#include "visors/safety/passive_safety.hpp"

namespace visors::gnc {

core::Result<FlightComponent> FlightComponent::create(const GncConfig& config, std::optional<OnboardNavigation> navigation) {
  const auto valid = validate(config);
  if (!valid.ok()) return valid.error();
  auto mpc = control::StochasticMpc::create(config.science.mpc);
  if (!mpc.ok()) return core::Error{"science.mpc." + mpc.error().field, mpc.error().message};
  return FlightComponent(config, std::move(mpc).value(), std::move(navigation));
}

FlightComponent::FlightComponent(const GncConfig& config, control::StochasticMpc mpc, std::optional<OnboardNavigation> navigation)
    : config_(config),
      mpc_(std::move(mpc)),
      queue_(config.maneuver_queue_capacity),
      active_(config.active),
      mass_kg_(config.mass_kg),
      navigation_(std::move(navigation)),
      geometry_(config.science.geometry),
      drag_(config.drag) {
  waypoints_.reserve(static_cast<std::size_t>(config.transfer.max_waypoints));
  plan_.impulses.reserve(control::kMaxClosedFormImpulses);
  ls_plan_.plan.impulses.reserve(control::kMaxLeastSquaresBurns);
  mpc_step_.remaining.reserve(static_cast<std::size_t>(config.science.mpc.planner.max_impulses));
}

GncOutputs FlightComponent::step(const GncInputs& inputs) { return step_validated(admit(inputs)); }

GncInputs FlightComponent::admit(const GncInputs& inputs) {
  GncInputs valid = inputs;
  const auto keep = [&](auto& slot, Channel channel) {
    if (!slot) return;
    if (const core::Status check = validate(*slot, inputs.t); !check) {
      slot.reset();
      telemetry_.rejected.count(rejection_reason(check.problem()), channel);
    }
  };
  keep(valid.time_at_tone, Channel::kTimeAtTone);
  keep(valid.navigation, Channel::kNavigation);
  keep(valid.crosslink, Channel::kCrosslink);
  keep(valid.command, Channel::kGroundCommand);
  keep(valid.propulsion, Channel::kPropulsion);
  keep(valid.gps, Channel::kGps);
  keep(valid.laser_range, Channel::kLaserRange);
  return valid;
}

GncOutputs FlightComponent::step_validated(const GncInputs& inputs) {
  GncOutputs out;
  // Nothing here can throw: the flight layers compile without exceptions (the flight profile of
  // the build) and a step allocates nothing (tests/gnc, counted at the malloc level).
  if (started_ && inputs.t < now_) {
    telemetry_.rejected.count(RejectionReason::kTimeBackwards, Channel::kTimeAtTone);  // nothing of the step is used
  } else {
    now_ = inputs.t;
    started_ = true;
    accept_inputs(inputs, out);
    if (!active_ && observation_ && now_ > observation_->end) observation_.reset();
    if (estimate_) check_safety();
    if (active_) run_control(out);
    release_maneuver(out);
  }
  out.mode = mode_;
  out.star_tracker_power = mode_ == Mode::kScience;
  out.lrf_power = mode_ == Mode::kScience;
  out.passive_safety_violated = safety_violated_ && mode_ != Mode::kManual && mode_ != Mode::kEscape;
  const bool stale = !estimate_ || since(last_navigation_) > config_.max_estimate_age_s;
  out.gnc_incapable = stale || consecutive_failures_ >= config_.max_planning_failures;
  telemetry_.t = now_;
  telemetry_.mode = mode_;
  telemetry_.active = active_;
  telemetry_.estimate_valid = !stale;
  if (estimate_) telemetry_.roe_mean_m = estimate_->chief_mean.a * estimate_->roe_mean;
  telemetry_.safety_checked = safety_checked_;
  telemetry_.safety_margin_m = safety_margin_m_;
  telemetry_.observations_done = observations_done_;
  telemetry_.roe_target_m.setZero();
  if (observation_ && estimate_) telemetry_.roe_target_m = estimate_->chief_mean.a * observation_->roe_target;
  telemetry_.pending_pieces = queue_.pending();
  telemetry_.drag_valid = drag_.valid();
  telemetry_.differential_drag_mps2 = drag_.along_track_mps2();
  telemetry_.star_tracker_power = out.star_tracker_power;
  telemetry_.lrf_power = out.lrf_power;
  telemetry_.gnc_incapable = out.gnc_incapable;
  telemetry_.passive_safety_violated = out.passive_safety_violated;
  if (navigation_) {
    telemetry_.navigation_valid = navigation_->valid();
    telemetry_.navigation_fixed = navigation_->fixed();
    telemetry_.navigation_update = navigation_->last_update();
    out.navigation = navigation_->telemetry(now_);
  }
  out.telemetry = telemetry_;
  fill_crosslink(out);
  return out;
}

// The step's valid inputs (step_validated) put to use.
void FlightComponent::accept_inputs(const GncInputs& inputs, GncOutputs& out) {
  if (inputs.time_at_tone) accept_attitude(*inputs.time_at_tone);
  if (inputs.propulsion) mass_kg_ = inputs.propulsion->mass_kg;
  if (inputs.command) apply_command(*inputs.command);
  if (inputs.crosslink && !active_) follow_peer(*inputs.crosslink, out);
  if (navigation_) {
    feed_navigation(inputs);
    if (inputs.crosslink) navigation_->add_peer(inputs.crosslink->navigation);
    if (const auto solution = navigation_->solve(now_)) (void)accept_solution(*solution, navigation_->last_update());
  } else if (inputs.navigation && !accept_solution(*inputs.navigation, inputs.navigation->t)) {
    telemetry_.rejected.count(RejectionReason::kNoOrbit, Channel::kNavigation);  // no estimate can be made of it
  }
}

void FlightComponent::accept_attitude(const TimeAtTone& tone) {
  if (has_attitude_ && tone.t > attitude_t_) {
    q_previous_ = q_body_to_gcrf_;
    previous_attitude_t_ = attitude_t_;
  }
  q_body_to_gcrf_ = tone.q_body_to_gcrf;
  attitude_t_ = tone.t;
  has_attitude_ = true;
}

void FlightComponent::feed_navigation(const GncInputs& inputs) {
  if (inputs.gps) {
    if (has_attitude_) {
      if (inputs.gps->has_ephemeris) navigation_->add_ephemeris(inputs.gps->ephemeris);
      navigation_->add_own_epoch(nav::receiver_epoch(inputs.gps->epoch), q_body_to_gcrf_);
    } else {
      telemetry_.rejected.count(RejectionReason::kNoAttitude, Channel::kGps);  // nothing to place the antenna with
    }
  }
  if (inputs.laser_range) navigation_->add_laser_range(*inputs.laser_range);
  const auto& p = inputs.propulsion;
  if (p && p->executed && has_attitude_) {
    // The body frame of the impulse is the attitude of its time (the step it fired).
    const Eigen::Quaterniond& q = p->t == previous_attitude_t_ ? q_previous_ : q_body_to_gcrf_;
    navigation_->add_own_impulse(ExecutedImpulse{p->t, q * p->dv_body_mps});
  }
}

bool FlightComponent::accept_solution(const NavigationSolution& solution, core::GpsTime measured) {
  auto estimate = estimate_from_navigation(solution, config_.gravity);
  if (!estimate.ok()) return false;
  estimate_ = std::move(estimate).value();
  last_navigation_ = measured;
  const double n = 2.0 * core::kPi / chief_period_s();
  drag_.observe(estimate_->t, estimate_->chief_mean.a * estimate_->roe_mean(astro::roe::kDa), n);
  return true;
}

void FlightComponent::apply_command(const GroundCommand& command) {
  using Kind = GroundCommand::Kind;
  switch (command.kind) {
    case Kind::kToManual: enter(Mode::kManual); break;
    case Kind::kToStandby:
      if (mode_ == Mode::kManual) enter(Mode::kStandby);
      break;
    case Kind::kStartScience:
      if (mode_ == Mode::kStandby) {
        observations_planned_ = command.observations;
        observations_done_ = 0;
        enter(Mode::kTransferToScience);
      }
      break;
    case Kind::kTransferToStandby:
      if (mode_ == Mode::kScience || mode_ == Mode::kTransferToScience) enter(Mode::kTransferToStandby);
      break;
    case Kind::kEscape:
      if (mode_ != Mode::kEscape) enter(Mode::kEscape);
      break;
    case Kind::kMakeActive: active_ = true; break;
    case Kind::kMakePassive:
      active_ = false;
      queue_.clear();
      break;
  }
}

void FlightComponent::follow_peer(const CrosslinkMessage& peer, GncOutputs& out) {
  if (!peer.sender_active) return;
  mode_ = peer.mode;
  observations_done_ = peer.observations_done;
  observations_planned_ = peer.observations_planned;
  if (peer.has_observation && (!observation_ || observation_->index != peer.observation_index)) {
    ScheduledObservation scheduled;
    scheduled.index = peer.observation_index;
    scheduled.slew_start = peer.slew_start;
    scheduled.start = peer.observation_start;
    scheduled.end = peer.observation_end;
    observation_ = scheduled;
    out.observation = ObservationCommand{now_, scheduled.index, scheduled.slew_start, scheduled.start, scheduled.end};
  }
}

void FlightComponent::enter(Mode mode) {
  mode_ = mode;
  queue_.clear();
  standby_checked_ = false;
  waypoints_.clear();
  leg_ = 0;
  leg_planned_ = false;
  observation_.reset();
  mpc_started_ = false;
  ls_planned_ = false;
  escape_planned_ = false;
}

void FlightComponent::check_safety() {
  if (safety_checked_ && since(last_safety_check_) < config_.safety.check_period_s) return;
  last_safety_check_ = now_;
  const auto assessment = safety::evaluate_passive_safety(estimate_->chief_mean, estimate_->roe_mean,
                                                          estimate_->roe_covariance, config_.safety, config_.gravity);
  if (!assessment.ok()) return;  // an estimate the check cannot use: keep the last verdict
  safety_checked_ = true;
  safety_margin_m_ = assessment->min_separation_margin_m;
  safety_violated_ = !assessment->safe;
}

double FlightComponent::chief_period_s() const {
  return safety::orbital_period(estimate_->chief_mean, config_.gravity.mu);
}

void FlightComponent::run_control(GncOutputs& out) {
  if (!estimate_ || since(last_navigation_) > config_.max_estimate_age_s) return;
  switch (mode_) {
    case Mode::kManual: break;
    case Mode::kStandby: run_standby(); break;
    case Mode::kTransferToScience:
    case Mode::kTransferToStandby: run_transfer(); break;
    case Mode::kScience: run_science(out); break;
    case Mode::kEscape: run_escape(); break;
  }
}

bool FlightComponent::replace_plan(std::span<const control::Impulse> impulses) {
  queue_.clear();
  if (queue_.add(estimate_->t, estimate_->chief_mean, impulses, mass_kg_, config_.buffer).ok()) {
    ++telemetry_.plans;
    consecutive_failures_ = 0;
    return true;
  }
  planning_failed();
  return false;
}

void FlightComponent::planning_failed() {
  ++telemetry_.planning_failures;
  ++consecutive_failures_;
}

void FlightComponent::run_standby() {
  if (!queue_.empty()) return;
  const double period = config_.standby_keeping.check_period_orbits * chief_period_s();
  if (standby_checked_ && since(last_standby_check_) < period) return;
  standby_checked_ = true;
  last_standby_check_ = now_;
  const double a = estimate_->chief_mean.a;
  const astro::RelativeOrbitalElements target = control::standby_roe(a, config_.standby);
  const astro::RelativeOrbitalElements deviation_m = a * (estimate_->roe_mean - target);
  const double de_m = std::hypot(deviation_m(astro::roe::kDex), deviation_m(astro::roe::kDey));
  const double dlambda_m = std::abs(deviation_m(astro::roe::kDlambda));
  if (de_m <= config_.standby_keeping.de_deadband_m && dlambda_m <= config_.standby_keeping.dlambda_threshold_m) return;
  control::ClosedFormSettings settings;
  settings.earliest_burn_s = config_.burn_latency_s;
  const double tf = config_.standby_keeping.plan_orbits * chief_period_s();
  astro::RelativeOrbitalElements aim = target;
  if (config_.standby_keeping.drag_compensation) aim -= drag_drift(tf);  // as the transfer legs (plan_leg)
  if (control::plan_closed_form_into(plan_, estimate_->chief_mean, estimate_->roe_mean, aim, tf, settings, config_.gravity).ok()) {
    replace_plan(plan_.impulses);
  } else {
    planning_failed();
  }
}

bool FlightComponent::start_transfer(const astro::RelativeOrbitalElements& target) {
  // At most transfer.max_waypoints legs (reserved; the planner refuses more rather than grow it).
  const auto legs = control::transfer_waypoints_into(waypoints_, estimate_->roe_mean, target, config_.transfer.waypoints);
  if (!legs.ok() || waypoints_.empty()) {
    waypoints_.clear();
    planning_failed();
    return false;
  }
  leg_ = 0;
  leg_planned_ = false;
  return true;
}

bool FlightComponent::plan_leg() {
  const double tf = config_.transfer.leg_orbits * chief_period_s();
  control::ClosedFormSettings settings;
  settings.earliest_burn_s = config_.burn_latency_s;
  settings.end_margin_s = config_.transfer.end_margin_s;
  settings.normal_burns = config_.transfer.normal_burns;
  leg_end_ = estimate_->t + tf;
  leg_planned_ = true;
  // The planner's model is linear, so aiming at target - drift lets the drag carry the formation
  // onto the waypoint.
  astro::RelativeOrbitalElements target = waypoints_[leg_];
  if (config_.transfer.drag_compensation) target -= drag_drift(tf);
  if (!control::plan_closed_form_into(plan_, estimate_->chief_mean, estimate_->roe_mean, target, tf, settings,
                                      config_.gravity)
           .ok()) {
    planning_failed();
    return false;
  }
  return replace_plan(plan_.impulses);
}

void FlightComponent::run_transfer() {
  if (waypoints_.empty()) {
    astro::RelativeOrbitalElements target;
    if (mode_ == Mode::kTransferToScience) {
      if (config_.science.choose_pole) {
        const auto north = choose_north_pole(estimate_->chief_mean, estimate_->t, config_.science, geometry_, config_.gravity);
        if (north.ok()) geometry_.north = *north;
      }
      const auto next = next_observation(estimate_->chief_mean, estimate_->t, 1, config_.science, geometry_, config_.gravity);
      if (!next.ok()) {
        planning_failed();
        return;
      }
      target = next->roe_target;
    } else {
      target = control::standby_roe(estimate_->chief_mean.a, config_.standby);
    }
    if (!start_transfer(target)) return;
  }
  if (!leg_planned_) {
    plan_leg();
    return;
  }
  if (now_ < leg_end_ || !queue_.empty()) return;
  ++leg_;
  leg_planned_ = false;
  if (leg_ < waypoints_.size()) return;
  enter(mode_ == Mode::kTransferToScience ? Mode::kScience : Mode::kStandby);
}

bool FlightComponent::schedule_observation(GncOutputs& out) {
  const auto next = next_observation(estimate_->chief_mean, estimate_->t, observations_done_ + 1, config_.science, geometry_,
                                     config_.gravity);
  if (!next.ok()) {
    planning_failed();
    return false;
  }
  if (!mpc_started_) mpc_epoch_ = estimate_->t;
  observation_ = *next;
  // The MPC hands over to the least-squares planner at the start of the fine-control window, so
  // its target is the aligned ROE carried back there by the free (J2) motion:
  // roe(t_ls) = Phi(t_aligned, t_ls)^-1 roe(t_aligned); otherwise its optimal impulses would
  // fall inside the window, where the least-squares plan replaces them.
  const double to_aligned = next->aligned.seconds_since(estimate_->t);
  const double window = config_.science.least_squares_window_s + 0.5 * config_.science.observation_duration_s;
  const astro::KeplerianElements chief_ls = astro::propagate_mean_j2(estimate_->chief_mean, to_aligned - window, config_.gravity);
  window_stm_inverse_ = astro::j2_roe_stm(chief_ls, window, config_.gravity).inverse();
  const astro::RelativeOrbitalElements roe_ls = window_stm_inverse_ * next->roe_target;
  const core::GpsTime handover = next->aligned - window;
  if (!mpc_.set_target(roe_ls, handover.seconds_since(mpc_epoch_)).ok()) planning_failed();
  mpc_started_ = true;
  last_mpc_ = now_ - 2.0 * config_.science.mpc_period_s;  // plan at once
  ls_planned_ = false;
  out.observation = ObservationCommand{now_, next->index, next->slew_start, next->start, next->end};
  return true;
}

void FlightComponent::run_science(GncOutputs& out) {
  if (!observation_) {
    if (!schedule_observation(out)) return;
  }
  if (now_ >= observation_->end) {
    ++observations_done_;
    observation_.reset();
    if (observations_done_ >= observations_planned_) enter(Mode::kTransferToStandby);
    return;
  }
  if (now_ >= observation_->slew_start) {
    queue_.clear();  // nothing fires during the slew and the observation
    return;
  }
  if (observation_->start.seconds_since(now_) <= config_.science.least_squares_window_s) {
    science_fine_control();
  } else {
    science_mpc();
  }
}

void FlightComponent::science_mpc() {
  if (since(last_mpc_) < config_.science.mpc_period_s) return;
  last_mpc_ = now_;
  const double t = estimate_->t.seconds_since(mpc_epoch_);
  // The estimated differential drag from now to the aligned time, carried back to the handover:
  // the MPC's plan compensates it ahead, so the fine-control burns, whose execution errors land
  // closest to the observation, only trim (the paper's reason (ii) for low sensitivity to them).
  const double to_aligned = observation_->aligned.seconds_since(estimate_->t);
  const astro::RelativeOrbitalElements drift = window_stm_inverse_ * drag_drift(to_aligned);
  if (!mpc_.step_into(mpc_step_, t, estimate_->chief_mean, estimate_->roe_mean, estimate_->roe_covariance, drift).ok()) {
    planning_failed();
    return;
  }
  if (!mpc_step_.replanned) return;
  for (auto& impulse : mpc_step_.remaining) impulse.t -= t;  // since the estimate time, the queue's epoch
  replace_plan(mpc_step_.remaining);
}

void FlightComponent::science_fine_control() {
  const double to_start = observation_->start.seconds_since(estimate_->t);
  const double to_aligned = observation_->aligned.seconds_since(estimate_->t);
  std::array<double, control::kMaxLeastSquaresBurns> burns{};
  int count = 0;
  // Usable burns: after the planning latency, and early enough that their pieces (centred on the
  // burn) end a plenum refill before the slew.
  const double slew_before = observation_->start.seconds_since(observation_->slew_start);
  for (int k = 0; k < config_.science.least_squares_burns; ++k) {
    const double before = config_.science.least_squares_burns_before_s[static_cast<std::size_t>(k)];
    const double t_burn = to_start - before;
    if (t_burn >= config_.burn_latency_s && before >= slew_before + config_.buffer.limits.spacing_s) burns[count++] = t_burn;
  }
  // Replan every least_squares_period_s on the newest estimate (the paper closes this loop about
  // every 45 s), but never while the pieces of a burn are being fired: they belong together.
  if (count == 0) return;
  if (ls_planned_ && since(last_ls_) < config_.science.least_squares_period_s) return;
  if (!queue_.empty() && queue_.next_time() <= now_ + config_.burn_latency_s + config_.buffer.limits.spacing_s) return;
  ls_planned_ = true;
  last_ls_ = now_;
  // Aim so that the differential drag still to come carries the formation onto the target.
  const astro::RelativeOrbitalElements target = observation_->roe_target - drag_drift(to_aligned);
  if (count == 1) {
    replan_last_burn(target, burns[0], to_aligned);
    return;
  }
  if (!control::plan_least_squares_into(ls_plan_, estimate_->chief_mean, estimate_->roe_mean, target, to_aligned,
                                        std::span<const double>(burns.data(), static_cast<std::size_t>(count)),
                                        config_.science.least_squares, config_.gravity)
           .ok()) {
    planning_failed();
    return;
  }
  replace_plan(ls_plan_.plan.impulses);
}

// One burn left: three unknowns cannot fix the six ROE, so the burn minimises the alignment
// errors themselves at the alignment time: the relative position error and the relative velocity
// error weighted by the ratio of their requirements (18 mm against 0.2 mm/s: 90 s), i.e. the
// weighted least-squares solution of  W C (x_target - Phi x0 - Phi Gamma dv) = 0,  C the ROE -> RTN
// map at t_aligned, W = diag(1, 1, 1, w, w, w).
void FlightComponent::replan_last_burn(const astro::RelativeOrbitalElements& target, double t_burn, double to_aligned) {
  const astro::KeplerianElements chief_aligned = astro::propagate_mean_j2(estimate_->chief_mean, to_aligned, config_.gravity);
  Eigen::Matrix<double, 6, 6> wc = astro::roe_to_rtn_matrix(chief_aligned, config_.gravity.mu);
  wc.bottomRows<3>() *= config_.science.last_burn_velocity_weight_s;
  const astro::RelativeOrbitalElements free =
      control::predict_roe(estimate_->chief_mean, estimate_->roe_mean, {}, to_aligned, config_.gravity);
  const Eigen::Matrix<double, 6, 3> m = wc * control::impulse_effect(estimate_->chief_mean, t_burn, to_aligned, config_.gravity);
  const Eigen::Matrix<double, 6, 1> miss = wc * (target - free);
  const Eigen::Matrix3d normal = m.transpose() * m;
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(normal);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12)) {
    planning_failed();
    return;
  }
  single_[0] = control::Impulse{t_burn, ldlt.solve(m.transpose() * miss)};
  replace_plan(single_);
}

astro::RelativeOrbitalElements FlightComponent::drag_drift(double horizon_s) const {
  astro::RelativeOrbitalElements drift = astro::RelativeOrbitalElements::Zero();
  if (!drag_.valid() || !(horizon_s > 0.0)) return drift;
  const int nodes = config_.science.drag_drift_nodes;
  const double h = horizon_s / nodes;
  const Eigen::Vector3d dv_rtn(0.0, drag_.along_track_mps2() * h, 0.0);
  for (int k = 0; k < nodes; ++k) {
    drift += control::impulse_effect(estimate_->chief_mean, (k + 0.5) * h, horizon_s, config_.gravity) * dv_rtn;
  }
  return drift;
}

void FlightComponent::run_escape() {
  if (!escape_planned_) {
    escape_planned_ = true;
    const auto escape = safety::plan_escape(estimate_->chief_mean, estimate_->roe_mean, estimate_->roe_covariance,
                                            config_.burn_latency_s, config_.escape, config_.gravity);
    if (!escape.ok()) {
      planning_failed();
      escape_planned_ = false;  // try again at the next step with a fresh estimate
      return;
    }
    single_[0] = escape->impulse;
    replace_plan(single_);
    return;
  }
  if (queue_.empty() && queue_.has_released()) enter(Mode::kManual);
}

void FlightComponent::release_maneuver(GncOutputs& out) {
  if (!active_ || mode_ == Mode::kManual || !has_attitude_ || !estimate_) return;
  if (!queue_.due(now_, config_.buffer.limits.spacing_s)) return;
  const QueuedPiece piece = queue_.pop(now_);
  drag_.maneuver(now_);
  // The DSC (chief) firing changes the ROE with the opposite sign of the same impulse of the OSC
  // (docs/conventions.md "Spacecraft and roles").
  const Eigen::Vector3d dv_rtn = config_.self == Spacecraft::kDsc ? Eigen::Vector3d(-piece.dv_rtn) : piece.dv_rtn;
  const Eigen::Vector3d dv_gcrf = estimate_->rtn_to_gcrf * dv_rtn;
  out.maneuver = ManeuverCommand{now_, q_body_to_gcrf_.conjugate() * dv_gcrf, dv_rtn};
}

void FlightComponent::fill_crosslink(GncOutputs& out) const {
  CrosslinkMessage message;
  message.t = now_;
  message.sender = config_.self;
  message.mode = mode_;
  message.sender_active = active_;
  message.observations_done = observations_done_;
  message.observations_planned = observations_planned_;
  if (observation_) {
    message.has_observation = true;
    message.observation_index = observation_->index;
    message.slew_start = observation_->slew_start;
    message.observation_start = observation_->start;
    message.observation_end = observation_->end;
  }
  if (navigation_) message.navigation = navigation_->crosslink();
  out.crosslink = message;
}

}  // namespace visors::gnc
