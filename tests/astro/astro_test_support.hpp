#pragma once
// Shared helpers of the astro tests: exact (nonlinear) reference computations that the linear
// models are checked against. Header-only; not part of the flight library.

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/rtn_frame.hpp"

namespace visors::astro::test {

inline constexpr double kDeg = core::kDegToRad;

/// VISORS chief (Guffanti et al., AAS 23-149, 2023, Table 5; docs/conventions.md) with the
/// project's constants: a = R_E + 500 km, e = 0.004, i = 97.8 deg, RAAN 157.5 deg, and argp 90 deg
/// (the perigee of the worked examples in docs/algorithms/relative-motion.md).
inline KeplerianElements visors_chief(double mean_anomaly_deg = 0.0) {
  const core::EarthGravityConstants g;
  return KeplerianElements{g.re + 500e3, 0.004, 97.8 * kDeg, 157.5 * kDeg, 90.0 * kDeg,
                           mean_anomaly_deg * kDeg};
}

/// Exact relative state of the deputy in the chief's RTN frame, velocity as seen in the rotating
/// frame (core::relative_state_rtn, whose sign conventions tests/core/test_rtn_frame.cpp pins),
/// stacked as [dr_rtn; dv_rtn] like the linear maps.
inline Eigen::Matrix<double, 6, 1> exact_rtn(const core::StateVector& chief,
                                             const core::StateVector& deputy) {
  const core::RelativeStateRtn rel = core::relative_state_rtn(chief, deputy);
  Eigen::Matrix<double, 6, 1> out;
  out << rel.dr_rtn, rel.dv_rtn;
  return out;
}

/// Point-mass plus J2 acceleration (inertial, z along the Earth's axis) [m/s^2].
inline Eigen::Vector3d j2_acceleration(const Eigen::Vector3d& r, const core::EarthGravityConstants& g) {
  const double r2 = r.squaredNorm();
  const double rn = std::sqrt(r2);
  const double z2_r2 = r.z() * r.z() / r2;
  const double factor = 1.5 * g.j2 * g.mu * g.re * g.re / (r2 * r2 * rn);
  Eigen::Vector3d acc = -g.mu / (r2 * rn) * r;
  acc.x() += factor * r.x() * (5.0 * z2_r2 - 1.0);
  acc.y() += factor * r.y() * (5.0 * z2_r2 - 1.0);
  acc.z() += factor * r.z() * (5.0 * z2_r2 - 3.0);
  return acc;
}

/// One classical fourth-order Runge-Kutta step of the J2 problem.
inline core::StateVector rk4_j2_step(const core::StateVector& s, double h, const core::EarthGravityConstants& g) {
  const Eigen::Vector3d k1r = s.v;
  const Eigen::Vector3d k1v = j2_acceleration(s.r, g);
  const Eigen::Vector3d k2r = s.v + 0.5 * h * k1v;
  const Eigen::Vector3d k2v = j2_acceleration(s.r + 0.5 * h * k1r, g);
  const Eigen::Vector3d k3r = s.v + 0.5 * h * k2v;
  const Eigen::Vector3d k3v = j2_acceleration(s.r + 0.5 * h * k2r, g);
  const Eigen::Vector3d k4r = s.v + h * k3v;
  const Eigen::Vector3d k4v = j2_acceleration(s.r + h * k3r, g);
  return core::StateVector{s.r + h / 6.0 * (k1r + 2.0 * k2r + 2.0 * k3r + k4r),
                           s.v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v)};
}

}  // namespace visors::astro::test
