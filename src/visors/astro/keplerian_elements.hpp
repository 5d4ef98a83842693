#pragma once
// Classical Keplerian elements and their conversion to and from an inertial Cartesian state
// (two-body, the frame is whatever inertial frame r and v are given in, normally GCRF).
//
// Singular cases, by convention (chosen so that the Cartesian round trip stays exact):
//  * circular (e < kCircularTolerance after conversion): e = 0, argp = 0, M = nu = argument of
//    latitude measured from the node;
//  * equatorial (sin i < kEquatorialTolerance, i = 0 or pi): raan = 0, so argp (or, if also
//    circular, M) is measured from the inertial x axis.

#include <Eigen/Core>

#include "visors/core/constants.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/core/status.hpp"

namespace visors::astro {

struct KeplerianElements {
  double a = 0.0;     // semi-major axis [m]
  double e = 0.0;     // eccentricity [-], 0 <= e < 1
  double i = 0.0;     // inclination [rad], 0 <= i <= pi
  double raan = 0.0;  // right ascension of the ascending node [rad]
  double argp = 0.0;  // argument of perigee [rad]
  double M = 0.0;     // mean anomaly [rad]
};

inline constexpr double kCircularTolerance = 1e-13;    // below: e = 0, argp = 0 [-]
inline constexpr double kEquatorialTolerance = 1e-13;  // sin i below: raan = 0 [-]

/// Checks a > 0, 0 <= e < 1, 0 <= i <= pi and finite angles; the error names the field ("a", ...).
core::Outcome<KeplerianElements> validate_keplerian(const KeplerianElements& elements);

/// Two-body Cartesian state of validated elements (no check; see keplerian_to_cartesian).
core::StateVector cartesian_from_keplerian(const KeplerianElements& elements, double mu);

/// Checked conversion: invalid elements or mu <= 0 ("mu") give a failed Outcome.
core::Outcome<core::StateVector> keplerian_to_cartesian(const KeplerianElements& elements,
                                                    double mu = core::EarthGravityConstants{}.mu);

/// Elements of an inertial state. Angles raan, argp, M are wrapped to [0, 2 pi). Rejects
/// non-finite input ("r", "v"), r = 0 ("r"), rectilinear motion ("v": zero angular momentum) and
/// parabolic or hyperbolic energy ("v"), mu <= 0 ("mu").
core::Outcome<KeplerianElements> cartesian_to_keplerian(const Eigen::Vector3d& r,
                                                       const Eigen::Vector3d& v,
                                                       double mu = core::EarthGravityConstants{}.mu);

/// True anomaly of the elements [rad], with the revolution count of M kept.
double true_anomaly(const KeplerianElements& elements);

}  // namespace visors::astro
