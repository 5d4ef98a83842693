#pragma once
// What the navigation filter hands to control and safety (Guffanti et al., AAS 23-149, 2023,
// sec. 4.2-4.3; docs/algorithms/cdgps-filter.md#relative-solution; the gnc
// layer's NavigationSolution): both spacecraft's centres of mass, the OSC's state relative to the
// DSC in the DSC's RTN frame (core::relative_state_rtn: position, and its rate seen in the
// rotating frame), and the 6x6 covariance of that relative state,
//   P_rel = J P J',  J = d [dr_rtn; dv_rtn] / d x (the scaled filter states),
//   dr_rtn = M (r_osc - r_dsc),  dv_rtn = M (v_osc - v_dsc) - M [omega x] (r_osc - r_dsc),
// with M the GCRF -> RTN rotation and omega the RTN frame's rate, both of the DSC. Their own
// dependence on the DSC's state is left out of J: it scales with the separation over the orbit
// radius (40 m / 6,900 km = 6e-6 of the absolute uncertainty), far below the relative one.

#include <Eigen/Core>

#include "visors/core/gps_time.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/nav/navigation_state.hpp"

namespace visors::nav {

struct RelativeSolution {
  core::GpsTime t;
  core::StateVector dsc_gcrf;                     // [m, m/s]
  core::StateVector osc_gcrf;                     // [m, m/s]
  core::RelativeStateRtn relative;                // OSC w.r.t. DSC, RTN [m, m/s]
  Eigen::Matrix<double, 6, 6> covariance_rtn = Eigen::Matrix<double, 6, 6>::Zero();  // [m^2, m^2/s, m^2/s^2]
};

/// From the filter's state and covariance (float or fixed) at epoch t. Allocation-free.
RelativeSolution relative_solution(core::GpsTime t, const NavVector& x, const NavMatrix& P);

}  // namespace visors::nav
