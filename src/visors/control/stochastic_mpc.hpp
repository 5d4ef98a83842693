#pragma once
// Stochastic MPC wrapper around the reachable-set planner (Guffanti et al., AAS 23-149, 2023,
// sec. 4.3, Algorithm #2; docs/algorithms/control.md#stochastic-mpc): the plan is kept while it
// still reaches the target in the statistical sense, and recomputed only when it does not.
//
// At each navigation update (t, mean ROE estimate x, covariance P) the remaining impulses are
// propagated to the target time tf in the planner's linear model (J2 STM and Gamma from the
// chief's mean elements at t):
//   mu_f = Phi(tf, t) x + sum_j Phi(tf, t_j) Gamma(t_j) dv_j,
//   P_f  = Phi P Phi' + sum_j Phi Gamma Q_j Gamma' Phi' + Q_f,
// with Q_j = sigma_j^2 I the execution error of impulse j (sigma_j = fraction |dv_j| + floor)
// and Q_f a terminal process noise. With e = mu_f - target, the squared Mahalanobis distance is
// d^2 = e' P_f^-1 e, chi-square with 6 degrees of freedom when the plan is right and the
// errors are Gaussian (a chi-square quantile applies to d^2, so the threshold on d is its square
// root). The MPC replans from t when d exceeds the threshold (or when there is no plan yet),
// unless t is inside the freeze window before tf (which avoids replanning storms near the target
// time; the planner also refuses horizons below its minimum).
//
// Accelerations outside the planner's J2 model (differential drag) enter as a known drift: the
// caller's prediction of their effect on the mean ROE at tf, added to mu_f. Since the model is
// linear, planning onto target - drift makes the drift carry the formation onto the target; the
// plan then compensates the disturbance ahead instead of leaving it to the last burns.
//
// Times are seconds since the MPC's epoch (the same t0 for the estimates and the impulses).

#include <vector>

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/control/impulse.hpp"
#include "visors/control/reachable_set_planner.hpp"
#include "visors/core/status.hpp"

namespace visors::control {

struct StochasticMpcSettings {
  ReachableSetSettings planner{};
  /// Replanning threshold on the Mahalanobis distance d (not d^2). Default: the 99% quantile of
  /// chi-square with 6 degrees of freedom, 16.812 (e.g. NIST/SEMATECH e-Handbook, table 1.3.6.7.4),
  /// so d > sqrt(16.812) = 4.100: a correct plan triggers a false replanning at 1% of the updates.
  double mahalanobis_threshold = 4.100;
  /// Maneuver execution error, 1-sigma per RTN axis: fraction * |dv| + floor. Defaults: 1% of the
  /// magnitude (a typical cold-gas/ACS pointing-plus-magnitude budget) and 0.1 mm/s.
  double execution_sigma_fraction = 0.01;
  double execution_sigma_floor_mps = 1e-4;
  /// Terminal process noise Q_f added to P_f (dimensionless mean ROE, symmetric PSD).
  Eigen::Matrix<double, 6, 6> terminal_process_noise = Eigen::Matrix<double, 6, 6>::Zero();
  /// No replanning when tf - t is below this [s]; the current plan is kept. Default: 0.15 orbit
  /// of the VISORS chief (851 s), above the planner's 0.1-orbit minimum horizon.
  double freeze_time_s = 851.0;
  /// A new plan's first impulse is no earlier than t + this [s] (burn preparation; the 10 s
  /// flight-software step).
  double burn_latency_s = 10.0;
};

struct MpcStep {
  bool replanned = false;
  /// Mahalanobis distance of the predicted terminal error with the plan held before this step
  /// (infinity when there was no plan).
  double mahalanobis = 0.0;
  /// The impulses still to execute (t_j >= t), after any replanning, sorted.
  std::vector<Impulse> remaining;
  /// Predicted terminal mean ROE with the remaining impulses and the drift [-].
  astro::RelativeOrbitalElements roe_final_predicted = astro::RelativeOrbitalElements::Zero();
};

class StochasticMpc {
 public:
  /// Validates the settings (fields named, "planner.*" for the planner's) and sets up the planner.
  static core::Result<StochasticMpc> create(const StochasticMpcSettings& settings = {});

  /// New goal: mean ROE `roe_target` at time tf; clears the plan. Errors "roe_target", "tf".
  core::Status set_target(const astro::RelativeOrbitalElements& roe_target, double tf);

  /// One navigation update. chief_mean_t: the chief's mean elements at t. Errors: "t" (non-finite,
  /// before the previous update or after tf), "roe_estimate" (non-finite), "covariance"
  /// (non-finite, not symmetric or not positive definite), "target" (no set_target yet), and the
  /// planner's errors when a replanning fails (the previous plan is then kept).
  core::Result<MpcStep> step(double t, const astro::KeplerianElements& chief_mean_t,
                             const astro::RelativeOrbitalElements& roe_estimate,
                             const Eigen::Matrix<double, 6, 6>& covariance);
  /// The same into `out` (out.remaining cleared and refilled: given capacity for the planner's
  /// max_impulses, a step allocates nothing, replanning included). `drift_tf`: the predicted
  /// effect at tf of accelerations the planner does not model [-] (error "drift_tf" when not
  /// finite).
  core::Status step_into(MpcStep& out, double t, const astro::KeplerianElements& chief_mean_t,
                               const astro::RelativeOrbitalElements& roe_estimate,
                               const Eigen::Matrix<double, 6, 6>& covariance,
                               const astro::RelativeOrbitalElements& drift_tf = astro::RelativeOrbitalElements::Zero());

  /// The current plan (absolute impulse times; executed impulses are dropped at each step).
  [[nodiscard]] const ManeuverPlan& plan() const { return plan_; }
  [[nodiscard]] int replan_count() const { return replans_; }
  [[nodiscard]] const StochasticMpcSettings& settings() const { return settings_; }

 private:
  StochasticMpc(const StochasticMpcSettings& settings, ReachableSetPlanner planner);

  StochasticMpcSettings settings_;
  ReachableSetPlanner planner_;
  ManeuverPlan plan_;
  ManeuverPlan fresh_;  // the replanning target, swapped with plan_ on success
  bool has_plan_ = false;
  bool has_target_ = false;
  astro::RelativeOrbitalElements target_ = astro::RelativeOrbitalElements::Zero();
  double tf_ = 0.0;
  double last_t_ = -1e300;
  int replans_ = 0;
};

}  // namespace visors::control
