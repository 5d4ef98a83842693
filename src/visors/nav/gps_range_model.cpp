#include "visors/nav/gps_range_model.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "visors/core/constants.hpp"
#include "visors/gnss/gps_constants.hpp"

namespace visors::nav {
namespace {

constexpr double kC = core::kSpeedOfLight;
constexpr int kLightTimeIterations = 3;  // each scales the change by |e.V_sat| / c <= 1.3e-5

// Satellite position and inertial velocity, GCRF, at t_tx = t + offset (offset = t_r - tau - t
// [s]): its ITRF state at t_tx, rotated about the pole by the Earth's turn omega (t - t_tx) into
// the ITRF axes of the epoch t (Sagnac: R3(omega tau) at t_r, plus the turn over
// t_r - t), then to GCRF with the matrix of t. The ephemeris is evaluated at t_tx rounded to the
// nanosecond (GpsTime) and moved linearly over the rest, so rho is smooth in the clock state.
// Inertial velocity: the Earth-fixed one plus omega x r.
struct SatelliteAtTransmission {
  Eigen::Vector3d r_gcrf;
  Eigen::Vector3d v_gcrf;
  double clock_m;
};

SatelliteAtTransmission satellite_at(core::GpsTime t, double offset, const gnss::BroadcastEphemeris& ephemeris,
                                     const Eigen::Matrix3d& itrf_to_gcrf) {
  const core::GpsTime t_tx = t + offset;
  const double rest = offset - t_tx.seconds_since(t);  // below 0.5 ns
  const gnss::GpsSatelliteState s = gnss::broadcast_state(ephemeris, t_tx);
  const Eigen::Vector3d r_itrf = s.r_ecef_m + s.v_ecef_mps * rest;
  const double angle = -core::kEarthRotationRate * offset;
  Eigen::Matrix3d turn;  // R3(omega (t - t_tx)): ITRF axes of t_tx expressed in those of t
  turn << std::cos(angle), std::sin(angle), 0.0, -std::sin(angle), std::cos(angle), 0.0, 0.0, 0.0, 1.0;
  const Eigen::Vector3d omega(0.0, 0.0, core::kEarthRotationRate);
  SatelliteAtTransmission out;
  out.r_gcrf = itrf_to_gcrf * (turn * r_itrf);
  out.v_gcrf = itrf_to_gcrf * (turn * (s.v_ecef_mps + omega.cross(r_itrf)));
  out.clock_m = kC * (gnss::l1_clock_bias_s(ephemeris, s) + s.clock_drift_sps * rest);
  return out;
}

}  // namespace

Eigen::Vector3d phase_centre_lever_gcrf_m(const ReceiverEstimate& receiver, const AntennaGeometry& antenna) {
  const Eigen::Vector3d lever_body = antenna.arp_body_m + antenna.pco_body_m + receiver.pco_error_body_m;
  return antenna.body_to_gcrf * lever_body;
}

RangePrediction predict_range(core::GpsTime t, const ReceiverEstimate& receiver, const AntennaGeometry& antenna,
                              const gnss::BroadcastEphemeris& ephemeris, core::OnboardEarthFrame& frame) {
  RangePrediction out;
  const double dt_r = -receiver.clock_m / kC;  // t_r - t [s]
  out.reception_time = t + dt_r;
  out.antenna_gcrf_m = receiver.r_gcrf_m + receiver.v_gcrf_mps * dt_r + phase_centre_lever_gcrf_m(receiver, antenna);
  const Eigen::Matrix3d itrf_to_gcrf = frame.gcrf_to_itrf_matrix(t).transpose();

  // The light-time iteration on the satellite's inertial motion about a first evaluation at the
  // guess (tau is within +/- 0.02 s of it): r + v d + a d^2 / 2 with the two-body acceleration,
  // off by the jerk, ~1e-10 m at 0.02 s; then one evaluation at the final transmission time,
  // which the iteration's own error reaches only through v / c ~ 1e-5. (Four evaluations of the
  // broadcast orbit before: 9 % of a closed-loop campaign's time.)
  constexpr double kGuessS = 0.075;  // [s], a LEO-to-GPS light time
  const SatelliteAtTransmission guess = satellite_at(t, dt_r - kGuessS, ephemeris, itrf_to_gcrf);
  const Eigen::Vector3d a_gcrf = -gnss::kGpsMu / std::pow(guess.r_gcrf.norm(), 3) * guess.r_gcrf;
  double tau = kGuessS;
  for (int k = 0; k < kLightTimeIterations; ++k) {
    const double d = kGuessS - tau;
    const Eigen::Vector3d r = guess.r_gcrf + guess.v_gcrf * d + 0.5 * d * d * a_gcrf;
    tau = (r - out.antenna_gcrf_m).norm() / kC;
  }
  const SatelliteAtTransmission sat = satellite_at(t, dt_r - tau, ephemeris, itrf_to_gcrf);
  const Eigen::Vector3d los = sat.r_gcrf - out.antenna_gcrf_m;
  out.range_m = los.norm();
  out.transmission_time = t + (dt_r - tau);
  out.satellite_gcrf_m = sat.r_gcrf;
  out.satellite_clock_m = sat.clock_m;
  out.line_of_sight_gcrf = los / out.range_m;

  const Eigen::RowVector3d e = out.line_of_sight_gcrf.transpose();
  const double D = 1.0 + e.dot(sat.v_gcrf.transpose()) / kC;
  out.d_position = -e / D;
  out.d_velocity = out.d_position * dt_r;
  out.d_pco_error = out.d_position * antenna.body_to_gcrf;
  out.d_clock = -e.dot((sat.v_gcrf - receiver.v_gcrf_mps).transpose()) / (kC * D);
  return out;
}

}  // namespace visors::nav
