#pragma once
// Formation keeping of `visors gnss-sim` ([gnss.maneuvers] keeping = true): a perfect-knowledge
// along-track law that holds the deputy's mean relative mean argument of latitude (and so the
// along-track separation) at its initial value against differential drag, and the relative
// eccentricity vector against the random walk of the random maneuver pairs (steps 1-4 below). It is a TEST HARNESS
// for navigation, not flight software: it reads the TRUE osculating states of both spacecraft
// (which the simulator knows), so that a long gnss-sim run stays on the 40 m science formation
// while the random maneuver pieces still exercise the filter in every direction.
//
// Law (evaluated once per burst, at its first commanded piece):
//  1. mean ROE of the deputy (OSC) w.r.t. the chief (DSC): osculating GCRF states ->
//     astro::cartesian_to_keplerian -> astro::mean_from_osculating (first-order J2, Brouwer-
//     Lyddane) -> astro::roe_from_keplerian (quasi-nonsingular ROE, D'Amico; docs/conventions.md),
//     dimensionless.
//  2. Drift of the mean relative mean argument of latitude (Keplerian part of D'Amico's ROE
//     dynamics: the (dlambda, da) term of the
//     ROE state transition matrix, D'Amico, "Autonomous formation flying in low Earth orbit",
//     Ph.D. thesis, TU Delft 2010, ch. 2; src/visors/astro/roe_stm.hpp):
//       d(dlambda)/dt = -(3/2) n da,   n = sqrt(mu / a_c^3) the chief's mean motion.
//     The da that removes the dlambda error e = dlambda - dlambda_target in one chief orbit
//     (2 pi / n): -(3/2) n (da_target - da_target0) 2 pi / n = -e, i.e.
//       da_target = da_target0 + (dlambda - dlambda_target) / (3 pi).
//     A positive e gives da_target > da_target0: a larger deputy orbit, a negative d(dlambda)/dt.
//     With one correction per burst (bursts_per_orbit 3) the error is reduced by a third at each
//     burst (a damped discrete loop).
//  3. Gauss variational equation for a (near-circular orbit, tangential impulse dv_T):
//       delta a = 2 dv_T / n,  i.e. delta(da) = 2 dv_T / (n a_c) for a deputy impulse;
//     an impulse of the chief changes da with the opposite sign (docs/conventions.md "Roles").
//     The deputy-equivalent tangential dv needed over the burst:
//       dv_T = (n a_c / 2) (da_target - da) - dv_T_planned,
//     dv_T_planned = the deputy-equivalent tangential part of the burst's random pieces (they are
//     known when the burst starts; without it the random pair's along-track part would be
//     cancelled twice and the formation would swing by tens of metres between bursts).
//     dv_T_planned covers the random pieces still to fly in the burst's PAIR (this burst and,
//     for the first burst of a pair, the second), so that the random pair flies as without
//     keeping and the correction is the keeping alone.
//  4. The relative eccentricity vector random-walks under the random pairs (impulses 1/3 orbit
//     apart do not cancel in de), which step 3 alone leaves: over a day |a de| grows from 35 m to
//     ~140 m. Gauss for a tangential impulse at the mean argument of latitude u (near-circular):
//       delta(de) = (2 dv_T / (n a_c)) (cos u, sin u)
//     (D'Amico's thesis, in-plane control; docs/conventions.md for the sign of a chief impulse).
//     With m >= 3 bursts evenly spaced in u (u_k = u_0 + 2 pi k / m), x_k = (n a_c / m)
//     (de_target - de) . (cos u_k, sin u_k) at the m bursts sum to zero (da unchanged) and give
//     sum x_k (cos u_k, sin u_k) = (n a_c / 2)(de_target - de): the de error removed in one orbit.
//     Each burst flies its x_0 and the next burst recomputes (receding horizon).

#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/core/result.hpp"

namespace visors::sim {

/// The law's inputs and outputs at one instant (all ROE dimensionless).
struct AlongTrackCorrection {
  astro::RelativeOrbitalElements mean_roe = astro::RelativeOrbitalElements::Zero();  // true, now
  double mean_motion_radps = 0.0;   // chief's mean motion n [rad/s]
  double chief_mean_a_m = 0.0;      // a_c [m]
  double da_target = 0.0;           // [-]
  double dv_t_deputy_mps = 0.0;     // deputy-equivalent tangential dv still to command [m/s]
  double chief_mean_u_rad = 0.0;    // chief's mean argument of latitude argp + M [rad]
};

/// Mean ROE of the deputy w.r.t. the chief from their osculating GCRF states (step 1 above).
/// Errors: the conversions' (field "chief" or "deputy").
core::Result<astro::RelativeOrbitalElements> mean_roe_from_states(const core::StateVector& chief_gcrf,
                                                                  const core::StateVector& deputy_gcrf,
                                                                  const core::EarthGravityConstants& gravity);

/// The along-track correction (steps 1-3) that brings dlambda back to target_roe's in one orbit.
/// `target_roe` dimensionless (a_c dROE / a_c); `planned_dv_t_deputy_mps` the deputy-equivalent
/// tangential dv the burst already commands (0 for none).
core::Result<AlongTrackCorrection> along_track_correction(const core::StateVector& chief_gcrf,
                                                          const core::StateVector& deputy_gcrf,
                                                          const astro::RelativeOrbitalElements& target_roe,
                                                          double planned_dv_t_deputy_mps,
                                                          const core::EarthGravityConstants& gravity);

/// Relative eccentricity keeping (step 4 in the file comment): the deputy-equivalent tangential dv
/// of this burst [m/s] that, with the same rule at the next bursts, brings the mean (dex, dey) back
/// to target_roe's in one orbit without changing da. 0 when bursts_per_orbit < 3 (two bursts
/// half an orbit apart cannot move de without da).
double eccentricity_tangential_dv_mps(const AlongTrackCorrection& now, const astro::RelativeOrbitalElements& target_roe,
                                      int bursts_per_orbit);

/// The scalar c to add along the unit tangential axis to a piece `random_rtn_mps` so that the
/// piece's |dv| lies in [min_dv_mps, max_dv_mps] (the propulsion's impulse range over the mass),
/// as close as possible to `wanted_mps`: the correction is clamped to fit under the maximum (the
/// random part is kept whole), and moved out of the band where the total would fall under the
/// minimum. When no c fits under the maximum, 0.
double fit_tangential_correction(const Eigen::Vector3d& random_rtn_mps, double wanted_mps, double min_dv_mps,
                                 double max_dv_mps);

}  // namespace visors::sim
