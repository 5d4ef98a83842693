#pragma once
// Closed-form, time-optimised impulsive planner in mean QNS ROE (Gaias & D'Amico, JGCD 38(6)
// 2015; Chernick & D'Amico, JGCD 41(2) 2018; docs/algorithms/control.md#closed-form-planner):
// tangential in-plane burns at the delta-e phased locations (plus, for the dlambda-dominant case,
// burns at the window ends) and one or two normal burns at the delta-i phased location, with J2
// (Koenig, Guffanti & D'Amico 2017 STM) and the eccentric control input matrix.
//
// Model: roe(tf) = Phi(tf, t0) roe0 + sum_k B(t_k) dv_k, B(t) = Phi(tf, t) Gamma(t), where
// Phi(tf, t) = astro::j2_roe_stm(chief(t), tf - t), Gamma(t) = astro::control_input_matrix(chief(t))
// and chief(t) = astro::propagate_mean_j2(chief_mean_t0, t) (secular J2 phase rate,
// docs/algorithms/relative-motion.md#secular-j2-rates).
//
// Algorithm:
//  1. Pseudostate w = roe_target - Phi(tf, t0) roe0 (absorbs the free J2 and da drift).
//  2. Normal burn(s): the delta-i phased time (u(t) = atan2 of the pre-image of w_i under the
//     differential nodal drift, mod pi), found on the exact B(t) by a secant iteration, sized to
//     hit w_i.
//  3. In plane: candidate times = delta-e phased times u(t) + argp_dot (tf - t) = phi_e + k pi
//     (the delta-e effect of a burn is rotated by argp_dot (tf - t) until tf) plus the window
//     ends and points a quarter and half orbit inside them. The tangential magnitudes minimise
//     sum |x_k| subject to the four in-plane rows (da, dlambda, dex, dey) of the exact B: an
//     l1 problem whose optimum is a basic solution, found by enumerating all 3- and 4-subsets of
//     the candidates (Carathéodory). In the Keplerian near-circular model this reproduces the
//     three-burn closed form (de- and da-dominant cases) and the end-burn solution of the
//     dlambda-dominant case (docs/algorithms/control.md#closed-form-planner).
//  4. Correction: the residual left by the first-order phasing (eccentric Gamma, J2 couplings) is
//     removed by the minimum-norm change of all impulse vectors, dv += M'(M M')^-1 r (6 x 3N), so
//     the plan is exact for the linear J2 model.
//
// Cost (tests/control/test_closed_form_planner.cpp, mission chief, J2): cost / bound = 1.00002
// (de), 1.0001 (de with the science da, dlambda), 0.9995 (da), 1.0026 (dlambda, 2 orbits: the
// tangential-only plan against the full dual bound), 0.9967 (out of plane; eccentric Gamma, see
// delta_v_lower_bound.hpp). A dlambda-dominant target whose delta-e the end burns cannot produce
// costs ~3% above the bound. Separate in-plane and normal burns cost in_plane + out_of_plane,
// whereas dv_lower_bound is the coupled bound hypot(in, out): for the standby -> science transfer
// the plan costs 0.329 m/s against a grid optimum of 0.246 m/s that merges the planes' burns (use
// the conic/reachable-set planner when that saving matters).
// Accuracy: exact in the linear J2 model (a||droe_f|| < 1e-6 m); in a J2-only numerical
// propagation the standby -> science transfer ends 0.24 m (1.5 orbits) / 0.26 m (3 orbits) from
// the target, mostly a*diy = -0.22 m: Gamma maps the impulse to osculating elements, and the
// mean-element jump differs by the O(J2) Jacobian of the mean/osculating map (~1e-3 of the
// 200 m delta-i change; an attribution, not separately verified).
//
// The Keplerian near-circular standby -> science plan (-29.3163, +54.1291, -26.2627 mm/s; 0.21933
// m/s normal at u = 84.58 deg mod 180) is reproduced (worked example in
// docs/algorithms/control.md#worked-example-standby-to-science). A normal burn's dix also drifts
// dlambda (-kappa F S tau dix, KGD17 eq. A6: 0.15 m per orbit for the VISORS 18.7 m of a dix):
// step 3 therefore plans the in-plane burns on the residual after the normal burn(s), and a pure
// out-of-plane target gets small tangential burns.
// No heap allocation except the returned impulse vector (none for plan_closed_form_into).

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/control/impulse.hpp"
#include "visors/control/impulse_effect.hpp"  // the linear model (impulse_effect, predict_roe)
#include "visors/core/constants.hpp"
#include "visors/core/status.hpp"

namespace visors::control {

struct ClosedFormSettings {
  double earliest_burn_s = 0.0;  // first allowed burn time since t0 [s]
  double end_margin_s = 0.0;     // the last allowed burn time is tf - end_margin [s]
  /// Minimum burn-window length in orbits (2 pi / u_dot): the first delta-e phased location lies
  /// within half an orbit of the window start and the three-burn solution needs another orbit
  /// after it (docs/algorithms/control.md#closed-form-planner), hence 1.5.
  double min_window_orbits = 1.5;
  /// 1: one normal burn; 2: the normal delta-v split into two equal burns one orbit apart (same
  /// phase), e.g. to respect a per-burn limit.
  int normal_burns = 1;
  /// Largest accepted terminal error of the linear model, a ||roe_f - roe_target|| [m].
  double terminal_tolerance_m = 1e-6;
};

/// Plan from the chief MEAN elements at t0, the mean ROE roe0 at t0 and the target mean ROE at
/// tf [s since t0]. Errors (field, problem): non-finite or invalid chief ("chief_mean_t0.<field>",
/// e >= 0.1, equatorial), invalid gravity constants ("gravity"), non-finite ROE ("roe0", "roe_target"), tf not finite ("tf"), invalid
/// settings ("settings.<field>"), burn window shorter than min_window_orbits ("tf": horizon too
/// short), a geometry the impulses cannot span ("roe_target": singular geometry).
core::Result<ManeuverPlan> plan_closed_form(const astro::KeplerianElements& chief_mean_t0,
                                            const astro::RelativeOrbitalElements& roe0,
                                            const astro::RelativeOrbitalElements& roe_target, double tf,
                                            const ClosedFormSettings& settings = {},
                                            const core::EarthGravityConstants& gravity = {});

/// Most impulses a closed-form plan has (in-plane candidates plus two normal burns).
inline constexpr std::size_t kMaxClosedFormImpulses = 14;

/// The same into `plan` (its impulse vector cleared and refilled: with capacity for
/// kMaxClosedFormImpulses nothing is allocated). On error `plan` is unspecified.
core::Status plan_closed_form_into(ManeuverPlan& plan, const astro::KeplerianElements& chief_mean_t0,
                                         const astro::RelativeOrbitalElements& roe0,
                                         const astro::RelativeOrbitalElements& roe_target, double tf,
                                         const ClosedFormSettings& settings = {},
                                         const core::EarthGravityConstants& gravity = {});

}  // namespace visors::control
