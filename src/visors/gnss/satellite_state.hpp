#pragma once
// Position, velocity and clock of one GPS satellite at one GPS system time, as the broadcast
// ephemeris, the almanac or a precise orbit gives it.

#include <Eigen/Core>

namespace visors::gnss {

struct GpsSatelliteState {
  Eigen::Vector3d r_ecef_m = Eigen::Vector3d::Zero();    // WGS-84 / ITRF at that time [m]
  Eigen::Vector3d v_ecef_mps = Eigen::Vector3d::Zero();  // Earth-fixed velocity [m/s]
  double clock_bias_s = 0.0;   // satellite clock offset from GPS time, incl. relativity [s]
  double clock_drift_sps = 0.0;  // its rate [s/s]
};

}  // namespace visors::gnss
