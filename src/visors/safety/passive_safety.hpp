#pragma once
// Passive-safety evaluation of a relative orbit given by its MEAN quasi-nonsingular ROE
// (Guffanti et al., AAS 23-149, 2023, sec. 2, safety requirements: the separation in the
// radial-normal plane, or in 3D, must stay above epsilon at q sigma over a horizon of T chief
// orbits; docs/algorithms/safety.md).
//
// Model. For t in [0, T]: roe(t) = Phi_J2(chief_mean_t0, t) roe0 (KGD17 eq. A6, always evaluated
// from t0, never chained), chief(t) = secular-J2 mean propagation of the chief, and the relative
// position r(t) = C(chief(t)) roe(t) with C the position rows of the eccentric first-order map
// (astro::roe_to_rtn_matrix, tau = 0). The RN separation is |(r_R, r_N)|, the 3D one |r|. This is
// the mean-ROE separation: short-period J2 terms (cm at VISORS scale) are not included.
//
// Minimisation. The separation is sampled `samples_per_orbit` times per chief orbit (Keplerian
// period 2 pi / n) and every local minimum of the samples (endpoints included) is refined by a
// golden-section search on the two neighbouring intervals down to 1e-4 s, so the minimum is the
// minimum of the model to ~1e-9 m, not of the grid. (For da = 0, e = 0 and no J2 this reproduces
// the closed form below to round-off; tests/safety/test_passive_safety.cpp.)
//
// Uncertainty (q sigma). The ROE covariance P0 (dimensionless, ROE^2) is propagated with the same
// STM, P(t) = Phi P0 Phi^T, and mapped to the separation d = |r| by its linearisation
// dd/droe0 = r_hat^T C Phi (r_hat = r / |r| in the RN plane or 3D): sigma_d^2 =
// r_hat^T C Phi P0 Phi^T C^T r_hat, i.e. the standard deviation of the separation ALONG the
// separation direction. (Where |r| = 0 the direction is undefined and sigma_d is taken as the
// square root of the largest eigenvalue of C P C^T, the conservative choice.) The margin is
// d(t) - q sigma_d(t), and min_separation_margin is its minimum over the horizon (refined like the
// separation, and never larger than min_separation - q sigma at t_min). safe = margin >= epsilon.
//
// No heap allocation per call (fixed-size Eigen only); invalid input returns a core::Status (no allocation either).
//
// Checks (tests/safety/test_passive_safety.cpp): the closed form below (re-derived there) equals
// 2e6-point sampling to 5e-10 m; for the science orbit it gives 18.91598 m, and near-circular
// sampling with a da = -2.62 m gives 18.827 m (worked example in
// docs/algorithms/safety.md#worked-example-the-science-orbit). The full model here gives 18.734 m
// for the science orbit over 1.5 orbits (eccentric map + J2 + da) and 199.20 m for the 200 m
// standby orbit. Parallel e/i vectors are the passively safe geometry (D'Amico & Montenbruck
// 2006); PERPENDICULAR e/i vectors make the radial and normal separations vanish together.

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/status.hpp"
#include "visors/safety/passive_safety_settings.hpp"

namespace visors::safety {

using RoeCovariance = Eigen::Matrix<double, 6, 6>;  // dimensionless ROE^2

struct SafetyAssessment {
  double min_separation_m = 0.0;         // minimum over the horizon of the nominal separation [m]
  double min_separation_margin_m = 0.0;  // minimum over the horizon of separation - q sigma [m]
  double t_min_s = 0.0;                  // time of min_separation since t0 [s]
  double t_min_margin_s = 0.0;           // time of min_separation_margin since t0 [s]
  double sigma_at_t_min_m = 0.0;         // 1-sigma of the separation at t_min [m]
  bool safe = false;                   // min_separation_margin >= epsilon
};

/// Closed-form minimum RN separation of a near-circular relative orbit with da = 0 and constant
/// ROE (D'Amico & Montenbruck 2006; docs/algorithms/safety.md#closed-form-rn-minimum):
///   a sqrt(2) |de . di| / sqrt(|de|^2 + |di|^2 + |de + di| |de - di|)   [m],
/// with de = (dex, dey), di = (dix, diy) and `a` the chief semi-major axis [m]. Derivation check:
/// r_R = -a|de| cos(u - phi), r_N = a|di| sin(u - theta) give min |r|^2 = (S - D)/2 with
/// S = |de|^2 + |di|^2 and D = |de + di||de - di|, which equals 2 (de.di)^2 / (S + D). Ignores
/// da, dlambda and J2; returns 0 for zero vectors.
double rn_separation_closed_form(const astro::RelativeOrbitalElements& roe, double a);

/// Keplerian period of the chief, 2 pi sqrt(a^3 / mu) [s] (the unit of horizon_orbits).
double orbital_period(const astro::KeplerianElements& chief, double mu);

/// Minimum separation (plane per settings) of the relative orbit over settings.horizon_orbits,
/// with its q-sigma margin. chief_mean: the chief's mean elements at t0 (validated, field
/// "chief.a" ...; equatorial chief rejected as "chief.i"); roe: mean ROE at t0 ("roe": finite);
/// covariance: symmetric positive semidefinite ("covariance"); settings validated (field names
/// of PassiveSafetySettings); gravity ("gravity.mu", "gravity.re", "gravity.j2").
core::Outcome<SafetyAssessment> evaluate_passive_safety(
    const astro::KeplerianElements& chief_mean, const astro::RelativeOrbitalElements& roe,
    const RoeCovariance& covariance, const PassiveSafetySettings& settings,
    const core::EarthGravityConstants& gravity = {});

/// The input checks of evaluate_passive_safety (shared with the escape planner).
core::Status validate_safety_inputs(const astro::KeplerianElements& chief_mean,
                                          const astro::RelativeOrbitalElements& roe,
                                          const RoeCovariance& covariance,
                                          const core::EarthGravityConstants& gravity);

}  // namespace visors::safety
