#include "visors/gnc/differential_drag_estimator.hpp"

namespace visors::gnc {

void DifferentialDragEstimator::maneuver(core::GpsTime t) {
  blocked_ = true;
  blocked_until_ = t + settings_.settle_s;
  has_baseline_ = false;
}

void DifferentialDragEstimator::observe(core::GpsTime t, double a_da_m, double mean_motion) {
  if (blocked_) {
    if (t < blocked_until_) return;
    blocked_ = false;
  }
  if (!has_baseline_) {
    has_baseline_ = true;
    baseline_t_ = t;
    baseline_value_ = a_da_m;
    return;
  }
  const double dt = t.seconds_since(baseline_t_);
  if (dt < settings_.baseline_s) return;
  const double measured = 0.5 * mean_motion * (a_da_m - baseline_value_) / dt;
  estimate_ = valid_ ? (1.0 - settings_.gain) * estimate_ + settings_.gain * measured : measured;
  valid_ = true;
  baseline_t_ = t;
  baseline_value_ = a_da_m;
}

}  // namespace visors::gnc
