#include "visors/sim/attitude_profile.hpp"

#include <cmath>

namespace visors::sim {
namespace {

constexpr double kDegenerateProjection = 1e-6;  // |projection| below which the velocity is used [-]
constexpr int kArrivalIterations = 8;           // fixed-point steps for the arrival time (file comment)
// Time a calibration yaw's return turn is followed after its nominal duration [s]: the turn's
// eigen-axis angle differs from the yaw by the nominal attitude's own motion, and slew() tracks the
// target once arrived, so the hand-over to the nominal branch is seamless.
constexpr double kCalibrationSlack_s = 10.0;

// Component of `v` normal to the unit vector `n`, normalised; `fallback` (same treatment) when
// that component is degenerate.
Eigen::Vector3d normal_part(const Eigen::Vector3d& v, const Eigen::Vector3d& n, const Eigen::Vector3d& fallback) {
  const Eigen::Vector3d p = v - v.dot(n) * n;
  if (p.norm() >= kDegenerateProjection) return p.normalized();
  return (fallback - fallback.dot(n) * n).normalized();
}

// Body-to-GCRF from the body X and Z axes expressed in GCRF (orthonormal): columns X, Y = Z x X, Z.
Eigen::Quaterniond from_axes(const Eigen::Vector3d& x_gcrf, const Eigen::Vector3d& z_gcrf) {
  Eigen::Matrix3d body_to_gcrf;
  body_to_gcrf << x_gcrf, z_gcrf.cross(x_gcrf), z_gcrf;
  return Eigen::Quaterniond(body_to_gcrf).normalized();
}

}  // namespace

// The query's state and the circular two-body prediction of the state at another time (file
// comment): r and v rotated about h = r x v by |h| / |r|^2 (t' - t).
struct AttitudeProfile::Context {
  double t_s;
  Eigen::Vector3d r_gcrf_m, v_gcrf_mps, sun_gcrf_unit, h_unit;
  double rate_radps;

  Context(double t, const Eigen::Vector3d& r, const Eigen::Vector3d& v, const Eigen::Vector3d& sun)
      : t_s(t), r_gcrf_m(r), v_gcrf_mps(v), sun_gcrf_unit(sun.normalized()), h_unit(r.cross(v).normalized()),
        rate_radps(r.cross(v).norm() / r.squaredNorm()) {}

  [[nodiscard]] Eigen::Quaterniond target(double t, Pointing pointing, double yaw_rad = 0.0) const {
    const Eigen::AngleAxisd turn(rate_radps * (t - t_s), h_unit);
    const Eigen::Vector3d r = t == t_s ? r_gcrf_m : Eigen::Vector3d(turn * r_gcrf_m);
    const Eigen::Vector3d v = t == t_s ? v_gcrf_mps : Eigen::Vector3d(turn * v_gcrf_mps);
    switch (pointing) {
      case Pointing::kObservation: return observation_body_to_gcrf(r, v, sun_gcrf_unit);
      case Pointing::kCalibration:  // nominal turned about its own +Z
        return (nominal_body_to_gcrf(r, v, sun_gcrf_unit) * Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ())))
            .normalized();
      case Pointing::kNominal: break;
    }
    return nominal_body_to_gcrf(r, v, sun_gcrf_unit);
  }
};

core::Result<bool> AttitudeSettings::validate() const {
  if (!std::isfinite(slew_rate_radps) || !(slew_rate_radps > 0.0)) {
    return core::Error{"slew_rate_radps", "must be a finite number > 0 rad/s"};
  }
  if (!std::isfinite(settling_s) || !(settling_s >= 0.0)) return core::Error{"settling_s", "must be finite and >= 0 s"};
  const CalibrationYaw& c = calibration;
  if (!(c.yaw_rad >= 0.0 && c.yaw_rad <= core::kPi)) return core::Error{"calibration.yaw_rad", "must be in [0, pi] rad"};
  if (!(std::isfinite(c.hold_s) && c.hold_s >= 0.0)) return core::Error{"calibration.hold_s", "must be finite and >= 0 s"};
  if (!(std::isfinite(c.first_s) && c.first_s >= 0.0)) return core::Error{"calibration.first_s", "must be finite and >= 0 s"};
  if (!(std::isfinite(c.margin_s) && c.margin_s >= 0.0)) return core::Error{"calibration.margin_s", "must be finite and >= 0 s"};
  if (!(std::isfinite(c.period_s) && c.period_s > 2.0 * c.yaw_rad / slew_rate_radps + c.hold_s + kCalibrationSlack_s)) {
    return core::Error{"calibration.period_s", "must be finite and longer than a yaw (two turns and the hold)"};
  }
  return true;
}

core::Result<AttitudeProfile> AttitudeProfile::create(const AttitudeSettings& settings) {
  if (auto ok = settings.validate(); !ok) return ok.error();
  return AttitudeProfile(settings);
}

core::Result<bool> AttitudeProfile::schedule(const ObservationWindow& w) {
  if (!std::isfinite(w.slew_start_s)) return core::Error{"slew_start_s", "must be finite"};
  if (!std::isfinite(w.start_s)) return core::Error{"start_s", "must be finite"};
  if (!std::isfinite(w.end_s)) return core::Error{"end_s", "must be finite"};
  if (w.slew_start_s > w.start_s) return core::Error{"slew_start_s", "must be <= start_s"};
  if (w.start_s > w.end_s) return core::Error{"end_s", "must be >= start_s"};
  if (!windows_.empty() && w.slew_start_s < windows_.back().end_s) {
    return core::Error{"slew_start_s", "must be >= the previous window's end_s (time order, no overlap)"};
  }
  windows_.push_back(w);
  return true;
}

double AttitudeProfile::slew_duration_s(double angle_rad) const { return std::abs(angle_rad) / settings_.slew_rate_radps; }

double AttitudeProfile::required_slew_lead_s(double angle_rad) const {
  return slew_duration_s(angle_rad) + settings_.settling_s;
}

Eigen::Quaterniond AttitudeProfile::nominal_body_to_gcrf(const Eigen::Vector3d& r_gcrf_m,
                                                         const Eigen::Vector3d& v_gcrf_mps,
                                                         const Eigen::Vector3d& sun_gcrf_unit) {
  const Eigen::Vector3d z = r_gcrf_m.normalized();
  return from_axes(normal_part(sun_gcrf_unit.normalized(), z, v_gcrf_mps), z);
}

Eigen::Quaterniond AttitudeProfile::observation_body_to_gcrf(const Eigen::Vector3d& r_gcrf_m,
                                                             const Eigen::Vector3d& v_gcrf_mps,
                                                             const Eigen::Vector3d& sun_gcrf_unit) {
  const Eigen::Vector3d x = sun_gcrf_unit.normalized();
  return from_axes(x, normal_part(r_gcrf_m.normalized(), x, v_gcrf_mps));
}

Eigen::Quaterniond AttitudeProfile::body_to_gcrf(double t_s, const Eigen::Vector3d& r_gcrf_m,
                                                 const Eigen::Vector3d& v_gcrf_mps,
                                                 const Eigen::Vector3d& sun_gcrf_unit) const {
  const Context context(t_s, r_gcrf_m, v_gcrf_mps, sun_gcrf_unit);
  if (const std::optional<double> start = calibration_start(t_s)) return in_calibration(*start, t_s, context);
  std::size_t count = 0;  // windows whose slew has begun by t_s
  while (count < windows_.size() && windows_[count].slew_start_s <= t_s) ++count;
  if (count == 0) return context.target(t_s, Pointing::kNominal);
  return in_window(count - 1, t_s, context);
}

// Attitude at t_s >= slew_start_s of window `index` (and before the next window's slew): the slew
// to the Sun from the attitude at slew start, the hold, the slew back to nominal.
Eigen::Quaterniond AttitudeProfile::in_window(std::size_t index, double t_s, const Context& context) const {
  const ObservationWindow& w = windows_[index];
  // Longest possible return slew of the previous window (pi rad): after it, it is surely nominal.
  const bool previous_settled =
      index == 0 || w.slew_start_s - windows_[index - 1].end_s >= slew_duration_s(core::kPi);
  const Eigen::Quaterniond q_start = previous_settled ? context.target(w.slew_start_s, Pointing::kNominal)
                                                      : in_window(index - 1, w.slew_start_s, context);
  if (t_s <= w.end_s) return slew(q_start, w.slew_start_s, t_s, Pointing::kObservation, context);
  const Eigen::Quaterniond q_end = slew(q_start, w.slew_start_s, w.end_s, Pointing::kObservation, context);
  return slew(q_end, w.end_s, t_s, Pointing::kNominal, context);
}

// Eigen-axis slew from q_from at t0_s towards the target where it is on arrival (file comment).
Eigen::Quaterniond AttitudeProfile::slew(const Eigen::Quaterniond& q_from, double t0_s, double t_s, Pointing to,
                                         const Context& context) const {
  const double rate = settings_.slew_rate_radps;
  const double yaw = settings_.calibration.yaw_rad;
  Eigen::Quaterniond q_to = context.target(t0_s, to, yaw);
  for (int k = 0; k < kArrivalIterations; ++k) {
    q_to = context.target(t0_s + rotation_angle_rad(q_from, q_to) / rate, to, yaw);
  }
  const double angle = rotation_angle_rad(q_from, q_to);
  if (t_s >= t0_s + angle / rate) return context.target(t_s, to, yaw);  // arrived: track
  // Rotation q_from -> q_to in body axes, shortest way (w >= 0): delta = q_from^-1 q_to.
  Eigen::Quaterniond delta = q_from.conjugate() * q_to;
  if (delta.w() < 0.0) delta.coeffs() = -delta.coeffs();
  const Eigen::Vector3d axis_body = delta.vec().normalized();
  return (q_from * Eigen::Quaterniond(Eigen::AngleAxisd(rate * (t_s - t0_s), axis_body))).normalized();
}

double AttitudeProfile::calibration_span_s() const {
  const CalibrationYaw& c = settings_.calibration;
  return 2.0 * slew_duration_s(c.yaw_rad) + c.hold_s + kCalibrationSlack_s;
}

// The start of the calibration yaw under way at t_s, if one is (CalibrationYaw): the latest
// first_s + k period_s <= t_s, while its span lasts and clear of every observation window.
std::optional<double> AttitudeProfile::calibration_start(double t_s) const {
  const CalibrationYaw& c = settings_.calibration;
  if (c.yaw_rad == 0.0 || !(t_s >= c.first_s)) return std::nullopt;
  const double start = c.first_s + std::floor((t_s - c.first_s) / c.period_s) * c.period_s;
  const double end = start + calibration_span_s();
  if (t_s > end) return std::nullopt;
  for (const ObservationWindow& w : windows_) {
    const double busy_from = w.slew_start_s - c.margin_s;
    const double busy_to = w.end_s + slew_duration_s(core::kPi) + c.margin_s;
    if (start < busy_to && end > busy_from) return std::nullopt;
  }
  return start;
}

// The yaw from the nominal attitude at start_s, the hold, the turn back (both at the slew rate).
Eigen::Quaterniond AttitudeProfile::in_calibration(double start_s, double t_s, const Context& context) const {
  const Eigen::Quaterniond q_start = context.target(start_s, Pointing::kNominal);
  const double hold_end_s = start_s + slew_duration_s(settings_.calibration.yaw_rad) + settings_.calibration.hold_s;
  if (t_s <= hold_end_s) return slew(q_start, start_s, t_s, Pointing::kCalibration, context);
  const Eigen::Quaterniond q_held = slew(q_start, start_s, hold_end_s, Pointing::kCalibration, context);
  return slew(q_held, hold_end_s, t_s, Pointing::kNominal, context);
}

double rotation_angle_rad(const Eigen::Quaterniond& qa, const Eigen::Quaterniond& qb) {
  const Eigen::Quaterniond delta = qa.conjugate() * qb;
  // 2 atan2(|vec|, |w|): accurate at small and large angles, unlike 2 acos(|w|).
  return 2.0 * std::atan2(delta.vec().norm(), std::abs(delta.w()));
}

double antenna_off_zenith_rad(const Eigen::Quaterniond& q_body_to_gcrf, const Eigen::Vector3d& r_gcrf_m) {
  const Eigen::Vector3d boresight_gcrf = q_body_to_gcrf * Eigen::Vector3d::UnitZ();
  return std::atan2(boresight_gcrf.cross(r_gcrf_m).norm(), boresight_gcrf.dot(r_gcrf_m));
}

}  // namespace visors::sim
