#pragma once
// Lower bounds on the total delta-v (sum of impulse norms) of the reduced impulsive boundary
// value problem in mean QNS ROE: reach the pseudostate w = roe_target - Phi(tf, t0) roe0 with
// impulses in a burn window of length `window` ending at tf.
//
// Source: weak duality of the minimum-fuel problem (Koenig & D'Amico, IEEE TAC 2021; Chernick &
// D'Amico 2018 for the near-circular closed forms; docs/algorithms/control.md#delta-v-lower-bounds):
// for any lambda,
//   J* >= lambda' w / max_t ||(Phi(tf,t) Gamma(t))' lambda||.
// Choosing lambda along single ROE components of the near-circular model gives the closed forms
//   da: (n/2) a|dda|,  de: (n/2) a||dde||,  di: n a||ddi_pre||,
// and lambda in the (da, dlambda) plane gives the dlambda bound (see DeltaVLowerBound::dlambda).
// J2 enters through the dlambda drift rate 1.5 n + 3.5 kappa E P (KGD17 eq. A6) instead of 1.5 n
// and the pre-image of di under the differential nodal drift
// (docs/algorithms/control.md#out-of-plane-bound-with-j2).
//
// Validity: first order in e. The eccentric Gamma (e = 0.004 for VISORS) changes the best
// single-burn effects by O(e), so a plan in the eccentric model may undercut these bounds by up to
// ~e relative. Measured against the conic solver's optimum on a 60 s grid (J2, eccentric Gamma,
// mission chief, 2 orbits; tests/control/test_delta_v_lower_bound.cpp): optimum / bound = 1.0002
// (de), 0.9966 (di: a normal burn near apogee is (1 + e) more effective), 1.0006 (dlambda), 1.0027
// (standby -> science, coupled planes: the hypot bound is tight there).
//
// Derived and verified here (docs/algorithms/control.md#the-dlambda-bound):
//  * the da, de, di closed forms, the eccentric da row bound a n eta|dda|/(2(1+e)), and the
//    standby -> science numbers of docs/algorithms/control.md#worked-example-standby-to-science
//    (1.45, 109.71 mm/s; 0.21933 m/s) hold;
//  * the tangential-only dlambda bound (n/2)|a dda + 4 a ddl/(3 du)| is NOT valid for du >= 4/3
//    rad, and there is no sharp switch to radial burns at du = 4/3 (a rule sometimes stated for
//    the near-circular case). An impulse with both radial and tangential components beats the
//    tangential pair for every du: the pure-dlambda bound is n a|ddl| / sqrt(c^2 + 4),
//    c = 1.5 du, and the (da, dlambda) gauge of the standby -> science transfer is 2.069 instead
//    of 2.09 mm/s. The tangential value is kept as dlambda_tangential.

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/status.hpp"

namespace visors::control {

/// Which in-plane bound is the largest (Gaias & D'Amico 2015, Chernick & D'Amico 2018 cases).
enum class InPlaneCase { kDa, kDe, kDlambda };

struct DeltaVLowerBound {
  double da = 0.0;  // (n/2) a |dda| [m/s]
  double de = 0.0;  // (n/2) a ||dde|| [m/s]
  /// Gauge of (a dda, a ddlambda) in the convex hull of the effects of unit impulses (any
  /// direction) in the window: the exact dual bound over lambda in the (da, dlambda) plane,
  /// near-circular model. A dv at t changes a da by 2 dv_T/n and, by tf, a dlambda by
  /// -2 (dv_R + c(t) dv_T)/n, with the lever arm c(t) = (1.5 n + 3.5 kappa E P)(tf - t); the
  /// support is largest at the window ends (convex in c), so with c = c(tf - window)
  ///   dlambda = max over lambda of lambda'(a dda, a ddl) n/2 subject to ||lambda|| <= 1 and
  ///             lambda_2^2 + (lambda_1 - c lambda_2)^2 <= 1,
  /// maximised numerically (dlambda_gauge). Pure dlambda has the closed form
  /// n a|ddlambda| / sqrt(c^2 + 4) [derived here], whose limits are the tangential pair's
  /// 2 n a|ddl| / (3 du) (c >> 2) and the radial burn's (n/2) a|ddl| (c -> 0). [m/s]
  double dlambda = 0.0;
  /// The same with tangential burns only (Chernick & D'Amico 2018):
  /// (n/2) max(a|dda|, a|dda + 2 ddlambda / c|), i.e. (n/2)|a dda + 4 a ddl/(3 du)| Keplerian.
  /// It bounds tangential-only plans (those of the closed-form planner) and exceeds `dlambda` by
  /// up to ~2/c^2 relative (1% at 1.5 orbits): combining a radial component with the first
  /// tangential burn is cheaper, so it is NOT a valid bound of the full problem, not even for
  /// du >= 4/3 rad. [m/s]
  double dlambda_tangential = 0.0;
  double in_plane = 0.0;      // max(da, de, dlambda) [m/s]
  double out_of_plane = 0.0;  // n a min_t ||ddi_pre(t)|| over the window [m/s]
  /// Bound of the coupled problem: hypot(in_plane, out_of_plane) (an impulse can serve both
  /// planes at once). Plans with separate in-plane and normal burns cost at least in + out. [m/s]
  double total = 0.0;
  InPlaneCase dominant = InPlaneCase::kDe;
};

/// Bounds for the chief MEAN elements `chief_mean` (at the start of the window; a, e, i are what
/// matter), the pseudostate `delta_roe` at tf [-] and the burn window length `window` [s].
/// Errors: invalid chief ("chief_mean.<field>"), e >= 0.1 ("chief_mean.e": near-circular
/// theory), equatorial chief ("chief_mean.i"), invalid gravity constants ("gravity"), non-finite ROE ("delta_roe"), window not finite or
/// not positive ("window").
core::Outcome<DeltaVLowerBound> delta_v_lower_bound(const astro::KeplerianElements& chief_mean,
                                                   const astro::RelativeOrbitalElements& delta_roe,
                                                   double window,
                                                   const core::EarthGravityConstants& gravity = {});

/// The (a dda, a ddlambda) gauge of DeltaVLowerBound::dlambda for a dlambda lever arm
/// `lever` = c [-] (dlambda change per unit da change from a tangential burn at the window start)
/// and mean motion n [rad/s]; a_dda, a_ddlambda in metres. [m/s]
double dlambda_gauge(double a_dda, double a_ddlambda, double lever, double n);

}  // namespace visors::control
