#pragma once
// The bus attitude determination and control system (ADCS) as the truth sees it (ground side of
// the simulator): the attitude it holds is the commanded one (sim/attitude_profile.hpp, slewing at
// the ADCS's own rate) rotated by its control error, and the attitude it reports to the flight
// software (time at tone) is that true attitude rotated by its determination error.
//
//   q_true     = q_commanded (x) dq(theta_pointing + theta_jitter)
//   q_reported = q_true      (x) dq(theta_knowledge)
//
// with dq(theta) the rotation by the small body-frame rotation vector theta (Hamilton,
// body-to-GCRF quaternions: docs/conventions.md), so each error is about the body axes.
// - theta_pointing: the control error, a first-order Gauss-Markov process per body axis,
//   x <- a x + sqrt(1 - a^2) sigma w, a = exp(-dt / tau), started from its stationary N(0, sigma);
// - theta_jitter: white per step, N(0, sigma) per axis (the wheels' and the controller's motion
//   faster than the 1 Hz step);
// - theta_knowledge: the star tracker's error, Gauss-Markov as the control error (tau = 0: white).
//
// Defaults: a Blue Canyon XACT-class bus as the paper's (BCT star tracker and reaction wheels). The
// one on-orbit characterisation of that unit (Mason et al. 2017, "MinXSS-1 CubeSat on-orbit
// pointing and power performance", JoSS 6(3) 651-662) measured a pointing accuracy of 15-42
// arcsec (3 sigma, axis dependent) and a peak-to-peak jitter of 26-66 arcsec over 10 s (3 sigma):
// 1 sigma per axis 5 / 14 / 5 arcsec and a jitter of a sixth of the peak-to-peak, 4.3 / 11 / 4.3.
// Knowledge: the BCT Nano Star Tracker's data-sheet accuracy, 6 arcsec across its boresight and
// 40 arcsec about it (1 sigma). The star tracker is taken to look out of a side face (body Y: the
// payload +X faces the Sun, the antenna +Z the zenith), so Y is the weak axis of both the
// knowledge and the control. The control error's correlation time (60 s) is an assumption, not
// a published figure: the slow part of an ADCS error follows the wheels' momentum and the
// disturbance torques over tens of seconds. docs/truth-and-knowledge.md has the reading.
//
// Consequence for the formation: the errors rotate the body vectors, 0.1-0.2 m lever arms to the
// payload points and the antenna, by ~1e-4 rad: ~10-30 um, two orders below the centimetre
// alignment budget, but present, as in flight.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "visors/core/constants.hpp"
#include "visors/core/result.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {

struct AdcsSettings {
  double slew_rate_radps = 1.5 * core::kDegToRad;  // the ADCS's eigen-axis slew rate [rad/s] (paper: 1.5 deg/s max)
  /// 1-sigma control error per body axis [rad] (Mason et al. 2017, file comment).
  Eigen::Vector3d pointing_sigma_rad = Eigen::Vector3d(5.0, 14.0, 5.0) * core::kArcsecToRad;
  double pointing_tau_s = 60.0;  // correlation time of the control error [s] (assumed, file comment)
  /// 1-sigma jitter per body axis, white at the step [rad] (Mason et al. 2017, file comment).
  Eigen::Vector3d jitter_sigma_rad = Eigen::Vector3d(4.3, 11.0, 4.3) * core::kArcsecToRad;
  /// 1-sigma determination error per body axis [rad] (star tracker data sheet, file comment).
  Eigen::Vector3d knowledge_sigma_rad = Eigen::Vector3d(6.0, 40.0, 6.0) * core::kArcsecToRad;
  double knowledge_tau_s = 0.0;  // correlation time of the determination error [s] (0: white)

  /// Ok, or the offending field by name (rate finite > 0; sigmas finite >= 0 and <= 1 deg; times
  /// finite >= 0).
  [[nodiscard]] core::Result<bool> validate() const;
};

class AdcsModel {
 public:
  /// Validates the settings (errors name the field); `rng` is the model's own stream.
  static core::Result<AdcsModel> create(const AdcsSettings& settings, RandomStream rng);

  /// Advances the errors to t_s [s] (called once a step, t_s increasing; the first call draws
  /// the stationary state). Nine normal draws a call, whatever the sigmas.
  void step(double t_s);

  /// The attitude the bus really holds when commanded to q_commanded (body-to-GCRF).
  [[nodiscard]] Eigen::Quaterniond true_attitude(const Eigen::Quaterniond& q_commanded_body_to_gcrf) const;
  /// The attitude the ADCS reports (time at tone) when the bus holds q_true (body-to-GCRF).
  [[nodiscard]] Eigen::Quaterniond reported_attitude(const Eigen::Quaterniond& q_true_body_to_gcrf) const;

  /// This step's control error (slow part plus jitter), body axes [rad].
  [[nodiscard]] Eigen::Vector3d pointing_error_body_rad() const { return pointing_rad_ + jitter_rad_; }
  /// This step's determination error, body axes [rad].
  [[nodiscard]] const Eigen::Vector3d& knowledge_error_body_rad() const { return knowledge_rad_; }
  [[nodiscard]] const AdcsSettings& settings() const { return settings_; }

 private:
  AdcsModel(const AdcsSettings& settings, RandomStream rng) : settings_(settings), rng_(std::move(rng)) {}

  AdcsSettings settings_;
  RandomStream rng_;
  Eigen::Vector3d pointing_rad_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d jitter_rad_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d knowledge_rad_ = Eigen::Vector3d::Zero();
  double t_s_ = 0.0;
  bool started_ = false;
};

/// The rotation by the rotation vector theta [rad] (exact, not the small-angle form).
Eigen::Quaterniond rotation_quaternion(const Eigen::Vector3d& theta_rad);

}  // namespace visors::sim
