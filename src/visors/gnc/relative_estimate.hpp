#pragma once
// The one place where the navigation solution (osculating Cartesian states, relative RTN
// covariance) becomes what control and safety work with (docs/conventions.md "Orbital
// elements"): the chief's mean elements, the mean ROE of the OSC w.r.t. the DSC, and its
// covariance.
//
// Mean elements: astro::mean_from_osculating (first-order J2 theory) of each spacecraft; the mean
// ROE is roe_from_keplerian of the two mean sets. Covariance: the relative RTN covariance mapped
// through the inverse of the first-order ROE -> RTN map at the osculating chief,
// P_roe = C^-1 P_rtn C^-T. (The osculating-to-mean difference is a near-identity map for the
// relative state at this separation, so the same matrix is used for the mean ROE; the error is
// O(J2) of the covariance, far below its own uncertainty.)

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/status.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/safety/passive_safety.hpp"

namespace visors::gnc {

struct RelativeEstimate {
  core::GpsTime t;
  core::StateVector chief_gcrf;                     // [m, m/s]
  Eigen::Matrix3d rtn_to_gcrf = Eigen::Matrix3d::Identity();  // columns R, T, N of the chief
  astro::KeplerianElements chief_mean;              // [m, rad]
  astro::RelativeOrbitalElements roe_mean = astro::RelativeOrbitalElements::Zero();  // [-]
  safety::RoeCovariance roe_covariance = safety::RoeCovariance::Zero();              // [-]
};

/// Errors name the navigation field whose conversion failed ("navigation.chief_gcrf", ...).
core::Outcome<RelativeEstimate> estimate_from_navigation(const NavigationSolution& navigation,
                                                        const core::EarthGravityConstants& gravity);

}  // namespace visors::gnc
