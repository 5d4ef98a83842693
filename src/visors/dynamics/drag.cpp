#include "visors/dynamics/drag.hpp"

#include <Eigen/Geometry>

namespace visors::dynamics {

Eigen::Vector3d relative_wind_gcrf(const core::StateVector& x_gcrf,
                                   const Eigen::Vector3d& omega_earth_gcrf) {
  // M&G sec. 3.5.1: the atmosphere moves with the Earth, at omega x r in the inertial frame.
  return x_gcrf.v - omega_earth_gcrf.cross(x_gcrf.r);
}

Eigen::Vector3d drag_acceleration(const core::StateVector& x_gcrf, double density, double cd,
                                  double area_m2, double mass_kg,
                                  const Eigen::Vector3d& omega_earth_gcrf) {
  const Eigen::Vector3d v_r = relative_wind_gcrf(x_gcrf, omega_earth_gcrf);  // [m/s]
  // M&G sec. 3.5.1: dynamic pressure 1/2 rho |v_r|^2 on area A, along -v_r.
  return (-0.5 * cd * (area_m2 / mass_kg) * density * v_r.norm()) * v_r;
}

}  // namespace visors::dynamics
