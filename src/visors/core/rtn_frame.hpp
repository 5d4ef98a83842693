#pragma once
// RTN (radial, transverse, normal) frame of a spacecraft and relative states in it
// (docs/conventions.md "Frames"):
//   R = r/|r|,  N = (r x v)/|r x v|,  T = N x R   (T is along-track for a near-circular orbit).
// Relative quantities are deputy minus chief, expressed in the chief's RTN. The relative velocity
// in RTN is the derivative seen in the rotating frame (transport theorem):
//   dr_rtn = M dr,   dv_rtn = M (dv - omega x dr),   omega = (r x v)/|r|^2,
// with M the GCRF->RTN matrix. omega is the RTN rate of a Keplerian orbit; a perturbing
// acceleration normal to the orbit adds a radial rate |r| a_N / |r x v| (J2 at 500 km: ~1e-6
// rad/s, i.e. ~5e-5 m/s for a 40 m separation), which is not modelled here. The alignment
// requirement is on the inertial relative velocity (dv), which is exact.
// Precondition for every function: r x v != 0 (not a rectilinear state).

#include <Eigen/Core>

#include "visors/core/earth_frames.hpp"  // StateVector

namespace visors::core {

struct RelativeStateRtn {
  Eigen::Vector3d dr_rtn = Eigen::Vector3d::Zero();  // deputy - chief position [m]
  Eigen::Vector3d dv_rtn = Eigen::Vector3d::Zero();  // its rate in the rotating RTN frame [m/s]
};

/// GCRF -> RTN rotation of the spacecraft with state `gcrf`: rows are R, T, N.
Eigen::Matrix3d gcrf_to_rtn_matrix(const StateVector& gcrf);

/// Angular velocity of the (Keplerian) RTN frame, omega = (r x v)/|r|^2, in GCRF [rad/s].
Eigen::Vector3d rtn_angular_velocity_gcrf(const StateVector& gcrf);

/// Deputy relative to chief in the chief's RTN.
RelativeStateRtn relative_state_rtn(const StateVector& chief_gcrf, const StateVector& deputy_gcrf);

/// Inverse of relative_state_rtn: the deputy's inertial state.
StateVector deputy_state_gcrf(const StateVector& chief_gcrf, const RelativeStateRtn& relative);

}  // namespace visors::core
