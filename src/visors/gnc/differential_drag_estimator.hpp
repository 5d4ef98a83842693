#pragma once
// On-board estimate of the differential along-track acceleration (differential drag: the two
// spacecraft differ in mass and so in ballistic coefficient), which the planners' J2 model does
// not contain. At 500 km and high solar activity it reaches ~1e-6 m/s^2 and moves the payloads by
// centimetres in the few minutes between the last fine-control burn and the observation, against an
// 18 mm requirement.
//
// Measurement: the Gauss variational equation of the semi-major axis for a near-circular orbit,
// d(a da)/dt = 2 a_T / n (a_T the differential along-track acceleration, n the mean motion), applied
// to the estimated MEAN relative semi-major axis (secular J2 does not change it): over a baseline of
// `baseline_s` without maneuvers, a_T = (n / 2) * change of a*da / baseline. Successive measurements
// are averaged with weight `gain`. A maneuver restarts the baseline (after `settle_s`).

#include "visors/core/gps_time.hpp"

namespace visors::gnc {

struct DifferentialDragSettings {
  /// Measurement baseline [s]. Short enough that one fits between the science approach's burns
  /// (150 s apart, settle included), so the estimate follows the drag of the last minutes before
  /// an observation instead of keeping the value of the last quiet stretch (the drag varies by a
  /// factor 3-4 over an orbit with density and attitude); long enough that the navigation's
  /// centimetre-level noise on a*da stays small against the change (0.16 m at 1e-6 m/s^2).
  double baseline_s = 90.0;
  double settle_s = 30.0;  // wait after a maneuver before a new baseline [s]
  double gain = 0.3;       // weight of a new measurement (0, 1] [-]
};

class DifferentialDragEstimator {
 public:
  explicit DifferentialDragEstimator(const DifferentialDragSettings& settings = {}) : settings_(settings) {}

  /// One estimate: t, a*da (mean) [m], the chief's mean motion n [rad/s].
  void observe(core::GpsTime t, double a_da_m, double mean_motion);
  /// A maneuver was commanded at t: the baseline restarts after settle_s.
  void maneuver(core::GpsTime t);
  void reset() { *this = DifferentialDragEstimator(settings_); }

  [[nodiscard]] bool valid() const { return valid_; }
  /// Differential along-track acceleration, deputy minus chief [m/s^2] (0 until valid).
  [[nodiscard]] double along_track_mps2() const { return estimate_; }

 private:
  DifferentialDragSettings settings_;
  bool has_baseline_ = false;
  core::GpsTime baseline_t_;
  double baseline_value_ = 0.0;
  bool blocked_ = false;
  core::GpsTime blocked_until_;
  bool valid_ = false;
  double estimate_ = 0.0;
};

}  // namespace visors::gnc
