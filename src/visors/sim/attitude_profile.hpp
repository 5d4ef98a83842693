#pragma once
// Truth attitude of one spacecraft (ground side of the simulator): nominal pointing, Sun pointing
// for observations, and the eigen-axis slews between them.
//
// Body frame: +Z = GPS antenna boresight, +X = payload line of sight (photon sieve on the OSC,
// detector on the DSC; both point +X at the Sun during an observation). Quaternions are
// body-to-GCRF, Hamilton, as everywhere in the project (docs/conventions.md).
//
// Target attitudes (both right-handed, Y = Z x X):
//   nominal:     Z = zenith r/|r|; X = the Sun projected on the plane normal to Z (as close to
//                the Sun as Z allows, keeps the solar arrays lit);
//   observation: X = Sun; Z = the zenith projected on the plane normal to X (antenna as close to
//                zenith as X allows).
// When the projection is degenerate (|projection| < 1e-6, Sun within 0.2 arcsec of the zenith or
// nadir) the velocity direction is projected instead.
//
// Slews: a rotation about the fixed eigen-axis from the attitude at the start of the slew to the
// target attitude at the arrival time, at the constant rate slew_rate_radps, then a settling time.
// The arrival time is a fixed point, t_arr = t0 + angle(q_from, target(t_arr)) / rate, solved by
// 8 substitutions (the map contracts by (target rate / slew rate) ~ 0.065 / 1.5 deg/s, so 8
// steps leave ~1e-11 of the first correction). Aiming at the target where it will be on arrival,
// rather than chasing the moving target, keeps the body rate exactly at the slew rate during the
// slew. After arrival the attitude tracks the target exactly. Settling is not modelled in the
// truth attitude (no residual oscillation); it only enters the lead time the flight side must
// allow: required_slew_lead_s = angle / rate + settling_s.
//
// Moving target during a slew: body_to_gcrf() gets the state only at the query time t, while a
// slew depends on the state at its start and at its arrival. Those are predicted from (r, v) at
// t by rotating both about the orbit normal h = r x v at the instantaneous rate |h| / |r|^2
// (exact for a circular two-body orbit). For the mission orbit (e = 0.004, n = 1.1e-3 rad/s) the
// predicted zenith is off by at most ~ e n^2 dt^2 = 7e-5 rad over dt = 120 s (a 180 deg slew),
// which shows up as a jump of that size at arrival. The Sun direction is taken as fixed over a
// slew (it moves 2e-7 rad/s).
//
// Schedule: windows are appended in time order and must not overlap (slew_start_s >= the previous
// window's end_s). The spacecraft holds the observation attitude from arrival through end_s, then
// slews back to nominal at the same rate. A window that begins before the previous return slew
// has certainly finished (pi / rate after its end_s) starts its slew from wherever the return slew
// is; one that begins later starts from the nominal attitude.

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "visors/core/constants.hpp"
#include "visors/core/result.hpp"

namespace visors::sim {

/// Calibration yaws of the nominal attitude (docs/phase-centre-estimation.md): a turn of yaw_rad
/// about body +Z (the antenna boresight, which stays at the zenith: the antenna sees the same
/// sky), a hold, and the turn back, each starting at first_s + k period_s [s, simulation time].
/// The observation slews all turn about body Y (nominal and observation attitudes share it), so
/// without a yaw the phase-centre offsets along Y, which the relative orbit cannot tell from an
/// along-track offset, are never observable. Both spacecraft fly the same plan, so the turn is
/// synchronous and the carrier wind-up cancels in the single differences. A yaw whose span would
/// come within margin_s of an observation window (its slew start to the end of a pi return
/// slew) is not flown; windows are scheduled at least ~2900 s ahead (gnc min_lead_s), more than
/// a yaw lasts. yaw_rad = 0: none.
struct CalibrationYaw {
  double yaw_rad = 0.0;       // [rad], in [0, pi]
  double hold_s = 120.0;      // [s] at the yawed attitude
  double period_s = 5700.0;   // [s] between yaw starts (about an orbit)
  double first_s = 1200.0;    // [s] the first yaw's start
  double margin_s = 300.0;    // [s] clearance from observation windows
};

/// Defaults (docs/requirements.md#gps-receiver-and-sensors): the slew rate of
/// Guffanti et al., AAS 23-149, 2023 ("paper"), sec. 5; the settling time is this project's.
struct AttitudeSettings {
  double slew_rate_radps = 1.5 * core::kDegToRad;  // eigen-axis slew rate [rad/s] (paper, sec. 5)
  double settling_s = 30.0;                        // settling time after a slew [s] (project choice)
  CalibrationYaw calibration{};                    // none by default

  /// Ok, or the offending field by name.
  [[nodiscard]] core::Result<bool> validate() const;
};

/// One observation [s, simulation time]: the slew towards the Sun begins at slew_start_s, the
/// observation itself spans [start_s, end_s].
struct ObservationWindow {
  double slew_start_s = 0.0;
  double start_s = 0.0;
  double end_s = 0.0;
};

class AttitudeProfile {
 public:
  /// Validates the settings (fields "slew_rate_radps", "settling_s").
  static core::Result<AttitudeProfile> create(const AttitudeSettings& settings = {});

  /// Appends an observation. Errors name the field: non-finite or slew_start_s > start_s
  /// ("slew_start_s"), start_s > end_s ("end_s"), slew_start_s before the previous end_s
  /// ("slew_start_s").
  core::Result<bool> schedule(const ObservationWindow& window);

  /// Truth attitude at t_s [s] from the spacecraft's state at t_s (r_gcrf_m [m], v_gcrf_mps [m/s])
  /// and the unit vector to the Sun (GCRF).
  [[nodiscard]] Eigen::Quaterniond body_to_gcrf(double t_s, const Eigen::Vector3d& r_gcrf_m,
                                                const Eigen::Vector3d& v_gcrf_mps,
                                                const Eigen::Vector3d& sun_gcrf_unit) const;

  /// Whether a calibration yaw (or its turns) is under way at t_s [s].
  [[nodiscard]] bool in_calibration_yaw(double t_s) const { return calibration_start(t_s).has_value(); }

  /// Duration of an eigen-axis slew through angle_rad at the configured rate [s].
  [[nodiscard]] double slew_duration_s(double angle_rad) const;
  /// Slew plus settling [s]: how long before start_s the slew must be commanded.
  [[nodiscard]] double required_slew_lead_s(double angle_rad) const;

  [[nodiscard]] const AttitudeSettings& settings() const { return settings_; }
  [[nodiscard]] const std::vector<ObservationWindow>& windows() const { return windows_; }

  /// The nominal and observation target attitudes (file comment), body-to-GCRF.
  static Eigen::Quaterniond nominal_body_to_gcrf(const Eigen::Vector3d& r_gcrf_m, const Eigen::Vector3d& v_gcrf_mps,
                                                 const Eigen::Vector3d& sun_gcrf_unit);
  static Eigen::Quaterniond observation_body_to_gcrf(const Eigen::Vector3d& r_gcrf_m,
                                                     const Eigen::Vector3d& v_gcrf_mps,
                                                     const Eigen::Vector3d& sun_gcrf_unit);

 private:
  explicit AttitudeProfile(const AttitudeSettings& settings) : settings_(settings) {}

  struct Context;  // the query's state and its circular-orbit predictor
  enum class Pointing { kNominal, kObservation, kCalibration };
  Eigen::Quaterniond in_window(std::size_t index, double t_s, const Context& context) const;
  Eigen::Quaterniond slew(const Eigen::Quaterniond& q_from, double t0_s, double t_s, Pointing to,
                          const Context& context) const;
  [[nodiscard]] double calibration_span_s() const;
  [[nodiscard]] std::optional<double> calibration_start(double t_s) const;
  Eigen::Quaterniond in_calibration(double start_s, double t_s, const Context& context) const;

  AttitudeSettings settings_;
  std::vector<ObservationWindow> windows_;
};

/// Angle of the rotation taking qa to qb, in [0, pi] [rad].
double rotation_angle_rad(const Eigen::Quaterniond& qa, const Eigen::Quaterniond& qb);

/// Angle between the GPS antenna boresight (+Z body) and the zenith r_gcrf_m / |r| [rad].
double antenna_off_zenith_rad(const Eigen::Quaterniond& q_body_to_gcrf, const Eigen::Vector3d& r_gcrf_m);

}  // namespace visors::sim
