#include "visors/core/rtn_frame.hpp"

#include <cassert>

#include <Eigen/Geometry>

namespace visors::core {

Eigen::Matrix3d gcrf_to_rtn_matrix(const StateVector& gcrf) {
  const Eigen::Vector3d h = gcrf.r.cross(gcrf.v);
  assert(h.norm() > 0.0 && "RTN is undefined for a rectilinear state (r x v = 0)");
  const Eigen::Vector3d r_hat = gcrf.r.normalized();
  const Eigen::Vector3d n_hat = h.normalized();
  const Eigen::Vector3d t_hat = n_hat.cross(r_hat);
  Eigen::Matrix3d m;
  m.row(0) = r_hat.transpose();
  m.row(1) = t_hat.transpose();
  m.row(2) = n_hat.transpose();
  return m;
}

Eigen::Vector3d rtn_angular_velocity_gcrf(const StateVector& gcrf) {
  return gcrf.r.cross(gcrf.v) / gcrf.r.squaredNorm();
}

RelativeStateRtn relative_state_rtn(const StateVector& chief_gcrf, const StateVector& deputy_gcrf) {
  const Eigen::Matrix3d m = gcrf_to_rtn_matrix(chief_gcrf);
  const Eigen::Vector3d omega = rtn_angular_velocity_gcrf(chief_gcrf);
  const Eigen::Vector3d dr = deputy_gcrf.r - chief_gcrf.r;
  const Eigen::Vector3d dv = deputy_gcrf.v - chief_gcrf.v;
  return {m * dr, m * (dv - omega.cross(dr))};
}

StateVector deputy_state_gcrf(const StateVector& chief_gcrf, const RelativeStateRtn& relative) {
  const Eigen::Matrix3d m_t = gcrf_to_rtn_matrix(chief_gcrf).transpose();
  const Eigen::Vector3d omega = rtn_angular_velocity_gcrf(chief_gcrf);
  const Eigen::Vector3d dr = m_t * relative.dr_rtn;
  const Eigen::Vector3d dv = m_t * relative.dv_rtn + omega.cross(dr);
  return {chief_gcrf.r + dr, chief_gcrf.v + dv};
}

}  // namespace visors::core
