#pragma once
// Guidance: the relative orbits the planners aim at.
//  - Standby: e/i-vector separation (D'Amico & Montenbruck 2006): a*de and a*di parallel, of
//    equal length rho (200 m) at a common phase, da = dlambda = 0: the RN separation never drops
//    below rho.
//  - Science: the optics spacecraft (OSC, the deputy) f = 40 m sunward of the detector (DSC, the
//    chief) at the observation time, with zero lateral inertial relative velocity (mission
//    requirement, Guffanti et al., AAS 23-149, 2023, sec. 2: lateral offset <= 18 mm, lateral
//    velocity <= 0.2 mm/s over 10 s). The observation is placed where the aligned position lies
//    in the TN plane, i.e. where the Sun direction is perpendicular to the radial direction:
//    u_obs = u_sun +/- 90 deg, which falls near the poles for the mission's orbit
//    (docs/algorithms/control.md#science-orbit). The ROE follow by inverting the eccentric
//    ROE -> RTN map at that time.
//  - Transfer: waypoints whose e and i vectors share one phase and move together from the start to
//    the target orbit (Guffanti et al., AAS 23-149, 2023, sec. 4.3, passively safe transfer
//    guidance; docs/algorithms/control.md#transfer-waypoints), so each intermediate orbit keeps
//    the e/i-vector separation; each leg is a 1.5-orbit closed-form maneuver.

#include <vector>

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/status.hpp"

namespace visors::control {

struct StandbyOrbit {
  double separation_m = 200.0;      // rho = a|de| = a|di| [m]
  double phase_rad = 1.5707963267948966;  // common phase of de and di [rad] (90 deg: de along ey)
};

/// Dimensionless ROE of the standby orbit for a chief of semi-major axis a [m].
astro::RelativeOrbitalElements standby_roe(double chief_a, const StandbyOrbit& orbit = {});

struct ScienceGeometry {
  double focal_distance_m = 40.0;  // OSC sunward of DSC [m]
  bool north = true;             // observe at u_sun + 90 deg (else u_sun - 90 deg)
  double los_rate_mps = 0.0;         // relative velocity along the Sun line [m/s] (0: hover)
  /// Lever arms of the payload reference points, r* = f s + offset_rtn (R_O p_O - R_D p_D, with
  /// p_O, p_D the payload points in the OSC and DSC body frames and R_O, R_D their body -> RTN
  /// attitudes; the sign for OSC minus DSC) [m].
  Eigen::Vector3d offset_rtn_m = Eigen::Vector3d::Zero();
  /// The commanded target on the solar disc: standard coordinates (xi east, eta north) about the
  /// apparent Sun centre (astro/apparent_sun.hpp) [rad]; (0, 0) is the disc centre.
  Eigen::Vector2d target_offset_rad = Eigen::Vector2d::Zero();
};

struct ScienceOrbit {
  double t_obs = 0.0;                        // first observation time after t0 [s since t0]
  double u_obs = 0.0;                        // chief mean argument of latitude there [rad]
  double beta = 0.0;                         // Sun elevation over the orbit plane [rad]
  Eigen::Vector3d sun_rtn = Eigen::Vector3d::Zero();  // unit Sun direction in the chief RTN at t_obs
  Eigen::Matrix<double, 6, 1> state_rtn = Eigen::Matrix<double, 6, 1>::Zero();  // [r (m); v (m/s)] at t_obs
  astro::RelativeOrbitalElements roe = astro::RelativeOrbitalElements::Zero();  // mean, at t_obs [-]
};

/// The aligned science orbit. `chief_mean_t0`: chief mean elements at t0 (GPS time `t0`); the Sun
/// line is the apparent direction of the commanded target seen from the chief at t_obs
/// (astro/apparent_sun.hpp). Errors: invalid elements or geometry, a Sun direction
/// too close to the orbit normal (|beta| > 89 deg: no TN-plane alignment).
core::Outcome<ScienceOrbit> science_orbit(const astro::KeplerianElements& chief_mean_t0, core::GpsTime t0,
                                         const ScienceGeometry& geometry = {},
                                         const core::EarthGravityConstants& gravity = {});

struct TransferSettings {
  double max_phase_step = 0.35;  // largest change of the common e/i phase per leg [rad] (20 deg)
  double max_size_ratio = 2.0;   // largest ratio of |de| (and |di|) between consecutive legs [-]
};

/// Waypoints from `from` to `to` (excluded, included): e and i vectors with one common phase,
/// phases and log-magnitudes interpolated, dlambda interpolated, da 0 until the final waypoint
/// (the target). Errors: non-finite input, a zero e or i vector at either end.
core::Result<std::vector<astro::RelativeOrbitalElements>> transfer_waypoints(
    const astro::RelativeOrbitalElements& from, const astro::RelativeOrbitalElements& to,
    const TransferSettings& settings = {});

/// The same into `waypoints` (cleared and refilled, never allocating); returns the number of
/// legs. Error "waypoints" when they would exceed its capacity (reserve it beforehand).
core::Outcome<int> transfer_waypoints_into(std::vector<astro::RelativeOrbitalElements>& waypoints,
                                          const astro::RelativeOrbitalElements& from,
                                          const astro::RelativeOrbitalElements& to,
                                          const TransferSettings& settings = {});

}  // namespace visors::control
