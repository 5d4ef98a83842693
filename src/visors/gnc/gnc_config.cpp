#include "visors/gnc/gnc_config.hpp"

#include <cmath>

namespace visors::gnc {

namespace {
bool positive(double x) { return std::isfinite(x) && x > 0.0; }
}  // namespace

core::Status validate(const GncConfig& config) {
  if (!positive(config.mass_kg)) return core::Status{core::Problem::kOutOfRange, "mass_kg", "must be > 0"};
  if (!positive(config.standby.separation_m)) return core::Status{core::Problem::kOutOfRange, "standby.separation_m", "must be > 0"};
  const auto& sk = config.standby_keeping;
  if (!positive(sk.check_period_orbits)) return core::Status{core::Problem::kOutOfRange, "standby_keeping.check_period_orbits", "must be > 0"};
  if (!positive(sk.de_deadband_m)) return core::Status{core::Problem::kOutOfRange, "standby_keeping.de_deadband_m", "must be > 0"};
  if (!positive(sk.dlambda_threshold_m)) return core::Status{core::Problem::kOutOfRange, "standby_keeping.dlambda_threshold_m", "must be > 0"};
  if (!(sk.plan_orbits >= 1.6 && std::isfinite(sk.plan_orbits))) {
    return core::Status{core::Problem::kOutOfRange, "standby_keeping.plan_orbits", "must be >= 1.6 (the closed-form window is 1.5 orbits)"};
  }
  if (!(config.transfer.leg_orbits >= 1.6 && std::isfinite(config.transfer.leg_orbits))) {
    return core::Status{core::Problem::kOutOfRange, "transfer.leg_orbits", "must be >= 1.6 (the closed-form window is 1.5 orbits)"};
  }
  if (config.transfer.normal_burns != 1 && config.transfer.normal_burns != 2) {
    return core::Status{core::Problem::kOutOfRange, "transfer.normal_burns", "must be 1 or 2"};
  }
  if (!(config.transfer.end_margin_s >= 0.0)) return core::Status{core::Problem::kOutOfRange, "transfer.end_margin_s", "must be >= 0"};
  if (config.transfer.max_waypoints < 1 || config.transfer.max_waypoints > kMaxTransferWaypoints) {
    return core::Status{core::Problem::kOutOfRange, "transfer.max_waypoints", core::in_range_text<1, kMaxTransferWaypoints>()};
  }
  if (!positive(config.drag.baseline_s)) return core::Status{core::Problem::kOutOfRange, "drag.baseline_s", "must be > 0"};
  if (!(config.drag.settle_s >= 0.0 && std::isfinite(config.drag.settle_s))) {
    return core::Status{core::Problem::kOutOfRange, "drag.settle_s", "must be finite and >= 0"};
  }
  if (!(config.drag.gain > 0.0 && config.drag.gain <= 1.0)) return core::Status{core::Problem::kOutOfRange, "drag.gain", "must be in (0, 1]"};
  const auto& sc = config.science;
  if (!positive(sc.least_squares_window_s)) return core::Status{core::Problem::kOutOfRange, "science.least_squares_window_s", "must be > 0"};
  if (sc.least_squares_burns < 1 || sc.least_squares_burns > control::kMaxLeastSquaresBurns) {
    return core::Status{core::Problem::kOutOfRange, "science.least_squares_burns",
                        core::in_range_text<1, control::kMaxLeastSquaresBurns>()};
  }
  for (int k = 0; k < sc.least_squares_burns; ++k) {
    const double b = sc.least_squares_burns_before_s[k];
    if (!(b > 0.0 && b <= sc.least_squares_window_s) || (k > 0 && !(b < sc.least_squares_burns_before_s[k - 1]))) {
      return core::Status{core::Problem::kOutOfRange, "science.least_squares_burns_before_s", "must be decreasing, > 0 and within least_squares_window_s"};
    }
  }
  if (!(sc.last_burn_velocity_weight_s >= 0.0)) return core::Status{core::Problem::kOutOfRange, "science.last_burn_velocity_weight_s", "must be >= 0"};
  if (!positive(sc.least_squares_period_s)) return core::Status{core::Problem::kOutOfRange, "science.least_squares_period_s", "must be > 0"};
  if (!positive(sc.mpc_period_s)) return core::Status{core::Problem::kOutOfRange, "science.mpc_period_s", "must be > 0"};
  if (!(sc.min_lead_s > sc.least_squares_window_s)) {
    return core::Status{core::Problem::kOutOfRange, "science.min_lead_s", "must exceed least_squares_window_s"};
  }
  if (!positive(sc.observation_duration_s)) return core::Status{core::Problem::kOutOfRange, "science.observation_duration_s", "must be > 0"};
  if (!positive(sc.slew_rate_radps)) return core::Status{core::Problem::kOutOfRange, "science.slew_rate_radps", "must be > 0"};
  if (!(sc.slew_settle_s >= 0.0)) return core::Status{core::Problem::kOutOfRange, "science.slew_settle_s", "must be >= 0"};
  if (!(sc.slew_margin_rad >= 0.0 && sc.slew_margin_rad <= core::kPi)) {
    return core::Status{core::Problem::kOutOfRange, "science.slew_margin_rad", "must be in [0, pi]"};
  }
  if (sc.drag_drift_nodes < 1 || sc.drag_drift_nodes > kMaxDragDriftNodes) {
    return core::Status{core::Problem::kOutOfRange, "science.drag_drift_nodes", core::in_range_text<1, kMaxDragDriftNodes>()};
  }
  if (const core::Status ok = safety::validate(config.safety); !ok) return ok.within("safety");
  if (const core::Status ok = safety::validate(config.escape); !ok) return ok.within("escape");
  if (!(config.burn_latency_s >= 0.0)) return core::Status{core::Problem::kOutOfRange, "burn_latency_s", "must be >= 0"};
  if (config.max_planning_failures < 1) return core::Status{core::Problem::kOutOfRange, "max_planning_failures", "must be >= 1"};
  if (!positive(config.max_estimate_age_s)) return core::Status{core::Problem::kOutOfRange, "max_estimate_age_s", "must be > 0"};
  if (config.maneuver_queue_capacity < 1 || config.maneuver_queue_capacity > kMaxManeuverQueuePieces) {
    return core::Status{core::Problem::kOutOfRange, "maneuver_queue_capacity", core::in_range_text<1, kMaxManeuverQueuePieces>()};
  }
  return {};
}

}  // namespace visors::gnc
