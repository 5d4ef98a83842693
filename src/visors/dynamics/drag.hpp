#pragma once
// Atmospheric drag on a cannonball (or any body whose drag area is given for the current wind),
// Montenbruck & Gill, Satellite Orbits (2000), sec. 3.5.1, eqs. 3.97-3.98:
//   a = -1/2 C_D (A / m) rho |v_r| v_r,   v_r = v - omega_E x r,
// with r, v the inertial (GCRF) state and v_r the velocity relative to an atmosphere co-rotating
// rigidly with the Earth (winds neglected: ~100 m/s at most, ~1 % of v_r at LEO).
//
// omega_earth_gcrf is the Earth's angular velocity expressed in GCRF. Exactly, it is
// earth_rotation_rate(eop) times the CIP direction, i.e. the third row of
// core::gcrf_to_itrf_matrix(t, eop) (R^T e_z). The usual approximation is (0, 0, omega_E)
// (earth_rotation_gcrf_approximate()): it ignores precession-nutation, whose CIP offset from the
// GCRF pole is X ~ 2004" per century since J2000, ~500" = 2.4e-3 rad in 2024, so the co-rotation
// velocity (~500 m/s at LEO) is tilted by ~1.2 m/s: a relative error <~2e-4 in v_r and <~3e-4 in
// the drag, far below the density-model error
// (docs/algorithms/dynamics.md#truth-and-on-board-mismatch).

#include <Eigen/Core>

#include "visors/core/constants.hpp"
#include "visors/core/state_vector.hpp"

namespace visors::dynamics {

/// (0, 0, omega_E) [rad/s], omega_E = 7.292115146706979e-5 (IERS 2010): the approximation above.
inline Eigen::Vector3d earth_rotation_gcrf_approximate() {
  return {0.0, 0.0, core::kEarthRotationRate};
}

/// Velocity relative to the co-rotating atmosphere, v - omega x r, in GCRF [m/s]: the flow
/// direction (its opposite) for attitude-dependent projected areas.
Eigen::Vector3d relative_wind_gcrf(const core::StateVector& x_gcrf,
                                   const Eigen::Vector3d& omega_earth_gcrf);

/// Drag acceleration in GCRF [m/s^2]. density [kg/m^3] (e.g. AtmosphereModel::density), cd [-],
/// area_m2 the area projected on the plane normal to the relative wind [m^2], mass_kg [kg],
/// omega_earth_gcrf [rad/s]. Hot path: no validation (precondition: finite, mass_kg > 0).
Eigen::Vector3d drag_acceleration(const core::StateVector& x_gcrf, double density, double cd,
                                  double area_m2, double mass_kg,
                                  const Eigen::Vector3d& omega_earth_gcrf);

}  // namespace visors::dynamics
