#include "visors/nav/relative_solution.hpp"

#include <Eigen/Geometry>

namespace visors::nav {

RelativeSolution relative_solution(core::GpsTime t, const NavVector& x, const NavMatrix& P) {
  RelativeSolution out;
  out.t = t;
  for (Craft c : {Craft::kDsc, Craft::kOsc}) {
    core::StateVector& s = c == Craft::kDsc ? out.dsc_gcrf : out.osc_gcrf;
    s.r = x.segment<3>(state::position(c));
    s.v = state::kVelocityUnit * x.segment<3>(state::velocity(c));
  }
  out.relative = core::relative_state_rtn(out.dsc_gcrf, out.osc_gcrf);
  const Eigen::Matrix3d M = core::gcrf_to_rtn_matrix(out.dsc_gcrf);
  const Eigen::Vector3d w = core::rtn_angular_velocity_gcrf(out.dsc_gcrf);
  Eigen::Matrix3d w_cross;
  w_cross << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
  Eigen::Matrix<double, 6, kNavStates> J = Eigen::Matrix<double, 6, kNavStates>::Zero();
  for (Craft c : {Craft::kDsc, Craft::kOsc}) {
    const double sign = c == Craft::kOsc ? 1.0 : -1.0;
    J.block<3, 3>(0, state::position(c)) = sign * M;
    J.block<3, 3>(3, state::position(c)) = -sign * M * w_cross;
    J.block<3, 3>(3, state::velocity(c)) = sign * state::kVelocityUnit * M;
  }
  out.covariance_rtn = J * P * J.transpose();
  out.covariance_rtn = (0.5 * (out.covariance_rtn + out.covariance_rtn.transpose())).eval();
  return out;
}

}  // namespace visors::nav
