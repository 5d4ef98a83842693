#include "visors/nav/orbit_time_update.hpp"

#include <algorithm>
#include <cmath>

#include "visors/core/rtn_frame.hpp"
#include "visors/nav/gauss_markov.hpp"

namespace visors::nav {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

Vector6 stack(const core::StateVector& x) {
  Vector6 y;
  y << x.r, x.v;
  return y;
}

core::StateVector unstack(const Vector6& y) { return {y.head<3>(), y.tail<3>()}; }

// d/dt (r, v) at t0 + s, with the empirical acceleration's mean at that instant.
Vector6 derivative(dynamics::ForceModel& model, core::GpsTime t0, double s, const Vector6& y,
                   const Eigen::Vector3d& a0_rtn, double tau) {
  model.set_empirical_acceleration_rtn(a0_rtn * std::exp(-s / tau));
  const core::StateVector x = unstack(y);
  Vector6 dy;
  dy << x.v, model.acceleration(t0 + s, x);
  return dy;
}

}  // namespace

MeanPropagation propagate_mean(dynamics::ForceModel& model, core::GpsTime t0, const core::StateVector& x0_gcrf,
                               const Eigen::Vector3d& a_emp_rtn_mps2, double tau_s, double dt_s, double max_step_s) {
  const int steps = std::max(1, static_cast<int>(std::ceil(dt_s / max_step_s - 1e-9)));
  const double h = dt_s / steps;
  Vector6 y = stack(x0_gcrf);
  for (int k = 0; k < steps; ++k) {
    const double s = k * h;
    const Vector6 k1 = derivative(model, t0, s, y, a_emp_rtn_mps2, tau_s);
    const Vector6 k2 = derivative(model, t0, s + 0.5 * h, y + 0.5 * h * k1, a_emp_rtn_mps2, tau_s);
    const Vector6 k3 = derivative(model, t0, s + 0.5 * h, y + 0.5 * h * k2, a_emp_rtn_mps2, tau_s);
    const Vector6 k4 = derivative(model, t0, s + h, y + h * k3, a_emp_rtn_mps2, tau_s);
    y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  model.set_empirical_acceleration_rtn(Eigen::Vector3d::Zero());
  return {unstack(y), a_emp_rtn_mps2 * std::exp(-dt_s / tau_s)};
}

Eigen::Matrix3d point_mass_gradient(const Eigen::Vector3d& r_gcrf, double gm) {
  const double r = r_gcrf.norm();
  const Eigen::Vector3d e = r_gcrf / r;
  return gm / (r * r * r) * (3.0 * e * e.transpose() - Eigen::Matrix3d::Identity());
}

MeanPropagation forecast_mean(dynamics::ForceModel& model, core::GpsTime t0, const core::StateVector& x0_gcrf,
                              const Eigen::Vector3d& a_emp_rtn_mps2, double tau_s, double dt_s, double gm) {
  model.set_empirical_acceleration_rtn(a_emp_rtn_mps2);
  const Eigen::Vector3d a = model.acceleration(t0, x0_gcrf);
  model.set_empirical_acceleration_rtn(Eigen::Vector3d::Zero());
  const Eigen::Vector3d j = point_mass_gradient(x0_gcrf.r, gm) * x0_gcrf.v;
  const double dt2 = dt_s * dt_s;
  core::StateVector x;
  x.r = x0_gcrf.r + x0_gcrf.v * dt_s + a * (0.5 * dt2) + j * (dt2 * dt_s / 6.0);
  x.v = x0_gcrf.v + a * dt_s + j * (0.5 * dt2);
  return {x, a_emp_rtn_mps2 * std::exp(-dt_s / tau_s)};
}

DynamicTransition dynamic_transition(const core::StateVector& x0_gcrf, const core::StateVector& x1_gcrf, double gm,
                                     double dt_s, double tau_s) {
  const Eigen::Matrix3d G0 = point_mass_gradient(x0_gcrf.r, gm);
  const Eigen::Matrix3d G1 = point_mass_gradient(x1_gcrf.r, gm);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double dt = dt_s;
  DynamicTransition phi = DynamicTransition::Zero();
  // First order in G, with G linear over the step: Phi_rr = I + int (dt-s) G(s) ds, Phi_rv =
  // dt I + int (dt-s) s G(s) ds, Phi_vr = int G(s) ds, Phi_vv = I + int s G(s) ds.
  phi.block<3, 3>(0, 0) = I + dt * dt * (G0 / 3.0 + G1 / 6.0);
  phi.block<3, 3>(0, 3) = dt * I + dt * dt * dt * (G0 + G1) / 12.0;
  phi.block<3, 3>(3, 0) = dt * (G0 + G1) / 2.0;
  phi.block<3, 3>(3, 3) = I + dt * dt * (G0 / 6.0 + G1 / 3.0);
  // Empirical acceleration, R the RTN -> GCRF rotation taken linear between the ends (the RTN
  // frame turns at the orbit rate): Phi_va = int R(s) E(s) ds, Phi_ra = int (dt-s) R(s) E(s) ds,
  // weighted to (R0 + R1)/2 and (2 R0 + R1)/3; plus the first-order gravity coupling of the
  // displacement it causes (R s^2/2 through G): G dt^3/6 R and G dt^4/24 R.
  const Eigen::Matrix3d R0 = core::gcrf_to_rtn_matrix(x0_gcrf).transpose();
  const Eigen::Matrix3d R1 = core::gcrf_to_rtn_matrix(x1_gcrf).transpose();
  const Eigen::Matrix3d G = 0.5 * (G0 + G1);
  // tau dt - tau^2 (1 - E1) and tau (1 - E1), evaluated without cancellation (nav/gauss_markov.hpp).
  const Eigen::Matrix3d chain = gauss_markov_chain(dt, tau_s, 0.0).transition;
  const double dt3 = dt * dt * dt;
  phi.block<3, 3>(0, 6) = chain(0, 2) * (2.0 * R0 + R1) / 3.0 + dt3 * dt / 24.0 * G * R0;
  phi.block<3, 3>(3, 6) = chain(1, 2) * (R0 + R1) / 2.0 + dt3 / 6.0 * G * R0;
  phi.block<3, 3>(6, 6) = chain(2, 2) * I;
  return phi;
}

}  // namespace visors::nav
