#pragma once
// The laser rangefinder measurement (docs/algorithms/cdgps-filter.md#laser-rangefinder; the OSC
// ranges to the DSC during observations, every 2 s: Guffanti et al., AAS 23-149, 2023, sec. 2 and
// Table 2): the distance between the two optical reference points,
//   z = |p_dsc - p_osc| + b + e,   p_k = r_k + C_k l_k,
// r_k the centre of mass (GCRF), C_k the body -> GCRF attitude, l_k the reference point's lever
// arm from the centre of mass in the body frame, b a known (calibrated) bias, e the noise.
// Partials with u = (p_dsc - p_osc)/|p_dsc - p_osc|: dz/dr_dsc = u', dz/dr_osc = -u'. The light
// time (130 ns at 40 m) and the motion during it are neglected. Only the component
// along the line of sight is constrained: at the science configuration the telescope's focal
// axis.

#include <Eigen/Core>

#include "visors/nav/gps_measurement_model.hpp"
#include "visors/nav/navigation_state.hpp"

namespace visors::nav {

struct LaserRangeGeometry {
  Eigen::Matrix3d dsc_body_to_gcrf = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d osc_body_to_gcrf = Eigen::Matrix3d::Identity();
  Eigen::Vector3d dsc_lever_body_m = Eigen::Vector3d::Zero();  // DSC optical point (target) from its CoM [m]
  Eigen::Vector3d osc_lever_body_m = Eigen::Vector3d::Zero();  // OSC optical point (LRF) from its CoM [m]
  double bias_m = 0.0;                                          // known range bias [m]
};

/// z predicted from x and its row (scaled states). Allocation-free.
MeasurementPrediction predict_laser_range(const NavVector& x, const LaserRangeGeometry& geometry);

}  // namespace visors::nav
