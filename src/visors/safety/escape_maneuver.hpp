#pragma once
// Single-impulse escape maneuver (Guffanti et al., AAS 23-149, 2023, sec. 4.3, Algorithm #4;
// docs/algorithms/safety.md#escape-maneuver): a single impulse, as soon as allowed after the
// trigger, reaching RN-plane separation from the e/i-vector conditions (Koenig & D'Amico, JGCD
// 41(8) 2018) and a relative semi-major axis giving a prescribed along-track drift, with the
// 3-sigma uncertainty accounted for (5 m of a*da drifts 47 m per orbit).
//
// Conditions imposed on the mean ROE just after the burn (all linear in dv_rtn through the
// eccentric control input matrix Gamma of astro::control_input_matrix at the burn):
//  (i)  a*da_after = s (da_target + q sigma_ada) with s = -sign(dlambda): since
//       d(a dlambda)/dt = -1.5 n a da, a deputy ahead (dlambda > 0) needs da < 0 so that dlambda
//       keeps growing, i.e. the deputy drifts AWAY from the chief (dlambda = 0: s = -1);
//       sigma_ada is the 1-sigma of a*da from the covariance, so the drift has at least the
//       prescribed rate (1.5 n da_target per unit time, 3 pi da_target per orbit) at q sigma;
//  (ii) de_after parallel (or antiparallel) to di_after along a common direction psi: two linear
//       equations, cross(de_after, d_psi) = 0 and cross(di_after, d_psi) = 0;
//  (iii) passive safety after the burn, evaluate_passive_safety in the settings' plane over the
//       settings' horizon with the post-burn covariance: margin = min separation - q sigma >=
//       epsilon.
// For each psi on a grid of `psi_samples` directions in [0, pi) (plus the phases of de and di
// themselves) (i)-(ii) is a 3x3 linear system for dv_rtn. Candidates are ranked by |dv| and the
// first one passing (iii) is kept. The burn time is the first time t_earliest + k time_step
// (within search_window_orbits) at which a candidate passes: "as soon as allowed".
//
// The near-circular relations dv_T = (n/2)(a da_target - a da), dv_R/n = -(d x de')/(d x e_R),
// dv_N/n = -(d x di)/(d x e_N) are the e = 0 limit of the system above (this code uses the
// eccentric Gamma instead; docs/algorithms/safety.md#escape-maneuver). Escape from the science
// orbit (worked example in docs/algorithms/safety.md#worked-example-escape-from-the-science-orbit;
// tests/safety/test_escape_maneuver.cpp): the tangential burn at u = phi_e + pi needs no R or N
// component only up to the 0.38 deg by which the science de and di are apart: exact parallelism
// costs dv_R = -0.26 mm/s (dv_T = -1.319 mm/s; |a de| 37.22 m). The RN minimum after the burn is
// 18.53 m in the eccentric J2 model over 1.5 orbits (18.66 m near-circular, static). The da term
// of the J2 drift, (1.5 n + 3.5 kappa E P) T a da, is 46.98 m per orbit; the STM's dix coupling
// (-kappa F S tau dix) brings the science escape to 46.82 m/orbit (numerical J2 propagation:
// 46.83 m/orbit).

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/control/impulse.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/status.hpp"
#include "visors/safety/passive_safety.hpp"

namespace visors::safety {

struct EscapeSettings {
  double epsilon_m = 5.0;             // required separation after the burn, at q sigma [m]
  double da_target_m = 5.0;           // |a da| after the burn, before the q-sigma allowance [m]
  double q_sigma = 3.0;               // [-]
  double horizon_orbits = 1.5;        // safety horizon after the burn [chief orbits]
  SafetyPlane plane = SafetyPlane::kRadialNormal;
  int samples_per_orbit = 120;        // safety sampling of each candidate [-]
  int psi_samples = 180;              // common e/i directions tried in [0, pi) [-]
  double time_step_s = 10.0;          // burn-time search step after t_earliest (>= 0.1) [s]
  double search_window_orbits = 1.0;  // latest burn: t_earliest + this many orbits [orbits]
  double dv_sigma_mps = 0.0;          // execution error, 1-sigma per RTN axis [m/s]
};

/// Each value checked; the error names the field ("epsilon_m", "da_target_m", ...).
core::Status validate(const EscapeSettings& settings);

struct EscapeManeuver {
  control::Impulse impulse;                         // t since t0 [s], dv_rtn [m/s]
  astro::RelativeOrbitalElements roe_before = astro::RelativeOrbitalElements::Zero();  // at t, mean [-]
  astro::RelativeOrbitalElements roe_after = astro::RelativeOrbitalElements::Zero();   // at t, mean [-]
  RoeCovariance covariance_after = RoeCovariance::Zero();  // at t [-]
  SafetyAssessment safety_after;                    // from t over the horizon (times since t)
  double drift_per_orbit_m = 0.0;  // change of a*dlambda over one orbit after the burn (J2 STM) [m]
};

/// Plans the escape. chief_mean_t0: chief mean elements at t0; roe, covariance at t0 (mean ROE,
/// dimensionless). t_earliest >= 0 [s since t0] ("t_earliest"). Input errors as in
/// evaluate_passive_safety; no safe candidate in the search window gives an Error with field
/// "escape".
core::Outcome<EscapeManeuver> plan_escape(const astro::KeplerianElements& chief_mean_t0,
                                         const astro::RelativeOrbitalElements& roe,
                                         const RoeCovariance& covariance, double t_earliest,
                                         const EscapeSettings& settings,
                                         const core::EarthGravityConstants& gravity = {});

}  // namespace visors::safety
