#pragma once
// The dynamic part of the filter's time update for one spacecraft
// (docs/algorithms/cdgps-filter.md#time-update):
//
// Mean: r' = v, v' = a_model(t, r, v) + R_rtn->gcrf(r, v) a_emp(t), integrated with classical RK4
// in sub-steps of at most max_step; the on-board force model (dynamics::ForceModel, configured as
// ForceModelConfig::onboard(): 20x20 gravity, Harris-Priester drag, SRP with shadow, Sun and Moon)
// gives a_model, and the empirical acceleration follows its Gauss-Markov mean,
// a_emp(t) = a_emp(t0) exp(-(t - t0)/tau), set on the model at each stage.
//
// Transition of (r [m], v [m/s], a_emp RTN [m/s^2]) over dt: a short-step approximation, first
// order in the point-mass gravity gradient G = (mu/r^3)(3 e e' - I)
// (docs/algorithms/cdgps-filter.md#state-transition), with G taken linear between the step's two
// ends instead of constant at its start:
//   Phi_rr = I + dt^2 (G0/3 + G1/6),  Phi_rv = I dt + dt^3 (G0 + G1)/12,
//   Phi_vr = dt (G0 + G1)/2,          Phi_vv = I + dt^2 (G0/6 + G1/3),
// (G0 held over the step is off by ~1e-6 in Phi_rr over 10 s, as e turns by v dt / r; this leaves
// the second order, ~1e-9; tests/nav/test_orbit_time_update.cpp), and
//   Phi_ra = R [tau dt - tau^2 (1 - E1)],  Phi_va = R tau (1 - E1),  Phi_aa = E1 I,  E1 = e^(-dt/tau),
// with the RTN -> GCRF rotation R taken linear between the ends ((2 R0 + R1)/3 and (R0 + R1)/2: the
// RTN frame turns by n dt = 1e-3 rad per second) and the first-order gravity coupling of the
// displacement the acceleration causes (G dt^4/24 R and G dt^3/6 R). Left: the J2 part of the
// gradient (1e-3 of G) and products of small terms, ~1e-7 relative over 10 s.
//
// SI units; the filter scales to its state units.

#include <Eigen/Core>

#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/dynamics/force_model.hpp"

namespace visors::nav {

using DynamicTransition = Eigen::Matrix<double, 9, 9>;  // (r, v, a_emp)

/// The state after dt > 0 [s] and the empirical acceleration's mean then; max_step > 0 [s].
struct MeanPropagation {
  core::StateVector x_gcrf;
  Eigen::Vector3d a_emp_rtn_mps2 = Eigen::Vector3d::Zero();
};
MeanPropagation propagate_mean(dynamics::ForceModel& model, core::GpsTime t0, const core::StateVector& x0_gcrf,
                               const Eigen::Vector3d& a_emp_rtn_mps2, double tau_s, double dt_s, double max_step_s);

/// The same over a short dt (the solution carried to the control's instant, ~1 s) from ONE
/// evaluation of the model at t0 instead of RK4's four: the Taylor expansion
///   r + v dt + a dt^2/2 + j dt^3/6,  v + a dt + j dt^2/2,  j = G v (the point-mass jerk, G the
/// gravity gradient of gm), a = a_model + R a_emp(t0). Left out: the J2 part of the jerk (~0.4 %
/// of G v) and the next order: 6.5e-6 m and 2e-5 m/s absolute at 1 s, far below the solution's
/// own absolute error (~1 m, 1.5 mm/s), and below 1e-9 between two spacecraft 40 m apart
/// (tests/nav/test_orbit_time_update.cpp, against propagate_mean). dt in (0, 2] s.
MeanPropagation forecast_mean(dynamics::ForceModel& model, core::GpsTime t0, const core::StateVector& x0_gcrf,
                              const Eigen::Vector3d& a_emp_rtn_mps2, double tau_s, double dt_s, double gm);

/// Phi of (r, v, a_emp) over dt from the states at the step's start and end (the mean
/// propagation's); gm [m^3/s^2], tau [s].
DynamicTransition dynamic_transition(const core::StateVector& x0_gcrf, const core::StateVector& x1_gcrf, double gm,
                                     double dt_s, double tau_s);

}  // namespace visors::nav
