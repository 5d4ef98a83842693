#pragma once
// Tikhonov-regularised least-squares impulses at 2-3 given times (VISORS fine control: Guffanti et
// al., AAS 23-149, 2023, sec. 4.3, Algorithm #3, eqs. 3-4;
// docs/algorithms/control.md#least-squares-planner): with B_k = a Phi(tf, t_k) Gamma(t_k) [s]
// (J2 STM, eccentric Gamma, chief propagated by the secular J2 rates; closed_form_planner.hpp)
// stacked as M = [B_1 ... B_m] (6 x 3m) and the pseudostate w = a (roe_target - Phi(tf, t0) roe0)
// [m],
//   v = argmin ||M v - w||^2 + nu ||v||^2 = (M'M + nu I)^-1 M' w = M'(M M' + nu I)^-1 w.
// The paper (eq. 4) prints the first form without the inverse; this is the regularised normal
// equation it stands for. The 6 x 6 form is used (cheaper, defined for any m). nu -> 0 gives the
// exact minimum-norm solution (it minimises sum ||dv_k||^2, not the fuel sum ||dv_k||). nu > 0
// trades terminal error for smaller impulses: the predicted terminal error is
// w - M v = nu (M M' + nu I)^-1 w.
//
// Keplerian near-circular standby -> science (worked example in
// docs/algorithms/control.md#worked-example-fixed-time-burns): burns at u = 90/270/450 deg leave
// dix unreachable (18.72 m residual with nu > 0); u = 45, 225, 405, 520 deg cost 0.4257 m/s
// exactly. Accuracy (tests/control/test_least_squares_planner.cpp; mission chief, J2, science ROE
// displaced by decimetres, 0.6 orbit): linear terminal error 4e-7 m; J2-only numerical
// propagation 1.7 cm (3 burns) and 1.8 cm (2 burns).
//
// nu [s^2] = relative_regularisation * trace(M M') / 6, i.e. relative to the mean eigenvalue of
// M M', so the default is independent of a and of the number of burns.

#include <span>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/control/impulse.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/status.hpp"

namespace visors::control {

struct LeastSquaresSettings {
  /// nu / (trace(M M') / 6) [-]. Default 1e-9: for well-spread burn times (smallest eigenvalue of
  /// M M' above 1e-4 of the mean) the regularisation error is below 1e-5 of ||w|| (sub-mm at the
  /// VISORS 200 m scale), while exact singularities still give a bounded plan.
  double relative_regularisation = 1e-9;
  /// Reciprocal condition number of M M' below which the geometry is rejected as singular when
  /// relative_regularisation is 0 (with nu > 0 the plan is bounded and is returned) [-].
  double min_reciprocal_condition = 1e-12;
};

struct LeastSquaresPlan {
  ManeuverPlan plan;  // dv_lower_bound = 0 (not computed)
  /// roe_target - roe_final_predicted of the linear model [-].
  astro::RelativeOrbitalElements terminal_error = astro::RelativeOrbitalElements::Zero();
  double nu = 0.0;  // the absolute regularisation used [s^2]
};

inline constexpr int kMaxLeastSquaresBurns = 6;

/// Impulses at `burn_times` [s since t0, in [0, tf], non-decreasing, 1..6 of them]. Errors:
/// invalid chief ("chief_mean_t0.<field>", e >= 0.1, equatorial), invalid gravity constants ("gravity"), non-finite ROE ("roe0",
/// "roe_target"), tf not finite or <= 0 ("tf"), bad times ("burn_times": count, finiteness,
/// order, range), bad settings ("settings.<field>"), and, with nu = 0, times whose M M' is
/// singular ("burn_times": singular geometry, e.g. all burns a multiple of pi apart in u, which
/// leaves one direction of delta-i unreachable).
core::Result<LeastSquaresPlan> plan_least_squares(const astro::KeplerianElements& chief_mean_t0,
                                                  const astro::RelativeOrbitalElements& roe0,
                                                  const astro::RelativeOrbitalElements& roe_target, double tf,
                                                  std::span<const double> burn_times,
                                                  const LeastSquaresSettings& settings = {},
                                                  const core::EarthGravityConstants& gravity = {});

/// The same into `out` (its impulse vector cleared and refilled: with capacity for
/// kMaxLeastSquaresBurns nothing is allocated). On error `out` is unspecified.
core::Status plan_least_squares_into(LeastSquaresPlan& out, const astro::KeplerianElements& chief_mean_t0,
                                           const astro::RelativeOrbitalElements& roe0,
                                           const astro::RelativeOrbitalElements& roe_target, double tf,
                                           std::span<const double> burn_times,
                                           const LeastSquaresSettings& settings = {},
                                           const core::EarthGravityConstants& gravity = {});

}  // namespace visors::control
