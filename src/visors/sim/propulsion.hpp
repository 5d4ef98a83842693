#pragma once
// Truth model of one spacecraft's cold-gas propulsion (ground side of the simulator).
//
// Actuator (Guffanti et al., AAS 23-149, 2023, sec. 2 and its propulsion table, Table 1(b);
// docs/requirements.md#propulsion): six nozzles on the body axes, impulse 1e-3 .. 2.2e-2 N s
// quantised in steps of 6e-5 N s, one impulse every 46.5 s (plenum refill), specific impulse 44 s.
// The spacing check allows 1 ns of round-off (the project's time resolution) so that impulses
// planned exactly 46.5 s apart are accepted.
//
// What one execute() does, in order:
//   1. rejects a non-finite time or command, and a time earlier than `spacing_s` after the previous
//      impulse (field "t_s");
//   2. converts the commanded velocity change to an impulse with the current (pre-burn) mass,
//      J = m |dv|, and rounds J to the nearest multiple of the quantum; a command whose unrounded
//      impulse is at most max_impulse but which rounds above it is set to the largest multiple not
//      above max_impulse (so the maximum itself is always executable); the quantised impulse must
//      lie in [min_impulse, max_impulse], else the command is rejected (field
//      "dv_commanded_body_mps"); a zero command is rejected the same way (below the minimum);
//   3. rejects the command when no propellant is left (field "dv_commanded_body_mps");
//   4. applies the errors: first each nozzle's bias (drawn once per run at creation, after the
//      specific impulse: six numbers N(0, magnitude_bias_sigma) for the +X, +Y, +Z, -X, -Y, -Z
//      nozzles, whatever the sigma), scaling each body component of the command by 1 + b of the
//      nozzle that fires it (the same paper, sec. 5, stresses calibrating thruster biases: a random
//      error averages out over the pieces of a burn, a bias does not); then, per impulse, the
//      magnitude J_q (1 + e_m) |c_b| / |c|, c_b the biased command, e_m ~ N(0, magnitude_sigma), clamped at zero
//      (a nozzle cannot push backwards; matters only for sigmas near 0.5); direction: the commanded
//      unit vector rotated about an axis perpendicular to it, at a uniformly random azimuth, by an
//      angle N(0, direction_sigma_rad), so the angle between commanded and executed directions has
//      RMS direction_sigma_rad and the error is isotropic about the command;
//   5. depletes the propellant with the rocket equation (Tsiolkovsky):
//      dm = m (1 - exp(-|dv_executed| / (Isp g0))), g0 = 9.80665 m/s^2. When dm exceeds what is
//      left the thruster fires what is left: the executed velocity change is shortened to
//      Isp g0 ln(m / (m - m_left)) along the same direction and the tank is empty afterwards;
//      later commands are rejected (step 3).
// Rejected commands draw nothing from the random stream; accepted ones draw three numbers (magnitude,
// azimuth, angle) whatever the sigmas, so a zero-error run has the same stream as a noisy one.
//
// The impulse-to-velocity conversion uses the pre-burn mass: the mass change of one maximum impulse
// (2.2e-2 N s / (44 s g0) = 5.1e-5 kg) changes |dv| by about dm / 2m = 2.4e-6 relative, far below
// the quantum (6e-5 / 2.2e-2 = 2.7e-3 relative at the maximum impulse).

#include <array>
#include <optional>

#include <Eigen/Core>

#include "visors/core/constants.hpp"
#include "visors/core/result.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {

/// Standard gravity, the conventional value used to define the specific impulse [m/s^2]
/// (CGPM 1901, exact).
inline constexpr double kStandardGravity = 9.80665;

struct PropulsionSettings {
  double min_impulse_ns = 1.0e-3;  // smallest executable impulse [N s] (paper table)
  double max_impulse_ns = 2.2e-2;  // largest executable impulse [N s] (paper table)
  double quantum_ns = 6.0e-5;      // impulse quantisation [N s] (paper table)
  double spacing_s = 46.5;         // minimum time between impulses, plenum refill [s] (paper table)
  /// 1-sigma magnitude error as a fraction of the impulse [-]. The mission's range is 0.05 .. 0.5;
  /// validate() accepts [0, 0.5] so that tests and ideal runs can switch it off.
  double magnitude_sigma = 0.05;
  /// 1-sigma direction error [rad] (0.05 deg by default). The mission's range is 0.05 .. 10 deg;
  /// validate() accepts [0, 10 deg].
  double direction_sigma_rad = 0.05 * core::kDegToRad;
  /// 1-sigma of each nozzle's magnitude bias, drawn once per run (step 4) [-]; validate() accepts
  /// [0, 0.5]. Off by default; the sensitivity study sweeps it.
  double magnitude_bias_sigma = 0.0;
  double isp_s = 44.0;        // mean specific impulse [s] (paper table)
  double isp_sigma_s = 2.0;   // 1-sigma of the true specific impulse, drawn once per run [s]

  /// Ok, or the first offending field by name.
  [[nodiscard]] core::Result<bool> validate() const;
};

/// What the thrusters actually did for one command.
struct ExecutedImpulse {
  double t_s = 0.0;                                                // execution time [s]
  Eigen::Vector3d dv_commanded_body_mps = Eigen::Vector3d::Zero();  // as commanded, body frame [m/s]
  Eigen::Vector3d dv_executed_body_mps = Eigen::Vector3d::Zero();   // truth, body frame [m/s]
  double impulse_ns = 0.0;         // quantised commanded impulse, an integer multiple of the quantum [N s]
  double propellant_used_kg = 0.0;  // [kg]
  double mass_after_kg = 0.0;       // spacecraft mass after the impulse [kg]
};

class Propulsion {
 public:
  /// Validates the settings and masses (fields "wet_mass_kg": finite, > 0; "propellant_kg": finite,
  /// in [0, wet_mass_kg)) and draws the true specific impulse N(isp_s, isp_sigma_s) from `rng`
  /// (field "isp_s" if the drawn value is not positive), then the six nozzle biases (step 4).
  static core::Result<Propulsion> create(const PropulsionSettings& settings, double wet_mass_kg,
                                         double propellant_kg, RandomStream rng);

  /// Executes a command at time t_s [s]; dv_commanded_body_mps in the spacecraft body frame [m/s].
  /// See the file comment for the steps and the rejections.
  core::Result<ExecutedImpulse> execute(double t_s, const Eigen::Vector3d& dv_commanded_body_mps);

  [[nodiscard]] double mass_kg() const { return mass_kg_; }
  [[nodiscard]] double propellant_kg() const { return propellant_kg_; }
  [[nodiscard]] double isp_s() const { return isp_s_; }  // the true (drawn) value [s]
  /// The drawn nozzle biases, +X, +Y, +Z, -X, -Y, -Z [-].
  [[nodiscard]] const std::array<double, 6>& nozzle_bias() const { return nozzle_bias_; }
  /// Time of the last executed impulse [s]; empty before the first.
  [[nodiscard]] std::optional<double> last_impulse_t() const { return last_impulse_t_; }
  [[nodiscard]] const PropulsionSettings& settings() const { return settings_; }

 private:
  Propulsion(const PropulsionSettings& settings, double wet_mass_kg, double propellant_kg, double isp_s,
             RandomStream rng);

  core::Result<double> quantised_impulse_ns(const Eigen::Vector3d& dv_commanded_body_mps) const;
  Eigen::Vector3d perturbed_direction(const Eigen::Vector3d& unit_body);

  PropulsionSettings settings_;
  double mass_kg_;
  double propellant_kg_;
  double isp_s_;
  RandomStream rng_;
  std::array<double, 6> nozzle_bias_{};
  std::optional<double> last_impulse_t_;
};

/// The delta-v budget metric of Guffanti et al., AAS 23-149, 2023, appendix: the L1 norm
/// |x| + |y| + |z| of a velocity change in the thrusters' (body) frame [m/s].
double thruster_l1_norm(const Eigen::Vector3d& dv_body);

}  // namespace visors::sim
