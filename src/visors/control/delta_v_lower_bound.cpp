#include "visors/control/delta_v_lower_bound.hpp"
#include "visors/control/impulse_effect.hpp"

#include <algorithm>
#include <cmath>

#include "visors/astro/j2_secular.hpp"

namespace visors::control {
namespace {

// Support function of the (a da, a dlambda) effects of unit impulses (radial and tangential
// components, lever arm c in [0, lever]) in the direction (l1, l2): the impulse u maps to
// (2 u_T, -2 (u_R + c u_T)) / n, so the support is ||(2 l1 - 2 c l2, -2 l2)|| / n, largest at an
// end of the window because it is convex in c.
double support(double l1, double l2, double lever, double n) {
  const double radial = 2.0 * l2;
  const double at_tf = std::hypot(2.0 * l1, radial);
  const double at_start = std::hypot(2.0 * l1 - 2.0 * lever * l2, radial);
  return std::max(at_tf, at_start) / n;
}

double ratio(double a_dda, double a_ddlambda, double lever, double n, double phi) {
  const double l1 = std::cos(phi);
  const double l2 = std::sin(phi);
  return std::abs(l1 * a_dda + l2 * a_ddlambda) / support(l1, l2, lever, n);
}

}  // namespace

double dlambda_gauge(double a_dda, double a_ddlambda, double lever, double n) {
  // Weak duality: every lambda gives a valid bound lambda'w / support(lambda); the gauge is the
  // maximum over the direction of lambda (homogeneous, so phi in [0, pi)). A dense scan followed
  // by a golden-section refinement of the best bracket; any phi evaluated is a valid bound, so an
  // imperfect maximisation can only make the bound lower, never invalid.
  constexpr int kSamples = 720;
  const double step = core::kPi / kSamples;
  int best = 0;
  double best_value = -1.0;
  for (int k = 0; k < kSamples; ++k) {
    const double v = ratio(a_dda, a_ddlambda, lever, n, k * step);
    if (v > best_value) {
      best_value = v;
      best = k;
    }
  }
  double lo = (best - 1) * step;
  double hi = (best + 1) * step;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo);
  double x2 = lo + g * (hi - lo);
  double f1 = ratio(a_dda, a_ddlambda, lever, n, x1);
  double f2 = ratio(a_dda, a_ddlambda, lever, n, x2);
  for (int it = 0; it < 60; ++it) {
    if (f1 < f2) {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = ratio(a_dda, a_ddlambda, lever, n, x2);
    } else {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = ratio(a_dda, a_ddlambda, lever, n, x1);
    }
  }
  return std::max({best_value, f1, f2});
}

core::Outcome<DeltaVLowerBound> delta_v_lower_bound(const astro::KeplerianElements& chief_mean,
                                                   const astro::RelativeOrbitalElements& delta_roe,
                                                   double window,
                                                   const core::EarthGravityConstants& gravity) {
  using namespace astro::roe;
  if (auto ok = validate_planner_chief(chief_mean, "chief_mean", gravity); !ok) return ok;
  if (!delta_roe.allFinite()) return core::Status{core::Problem::kNotFinite, "delta_roe", "must be finite"};
  if (!std::isfinite(window) || window <= 0.0) return core::Status{core::Problem::kOutOfRange, "window", "must be finite and positive"};

  const astro::J2SecularRates rates = astro::j2_secular_rates(chief_mean, gravity);
  const double n = rates.n;
  const double a = chief_mean.a;
  const double eta = std::sqrt((1.0 - chief_mean.e) * (1.0 + chief_mean.e));
  const double ci = std::cos(chief_mean.i);
  const double si = std::sin(chief_mean.i);
  // KGD17 eq. (A6): d(dlambda)/dt = -(1.5 n + 3.5 kappa E P) da, E = 1 + eta, P = 3 cos^2 i - 1.
  const double drift = 1.5 * n + 3.5 * rates.kappa * (1.0 + eta) * (3.0 * ci * ci - 1.0);
  const double lever = drift * window;

  DeltaVLowerBound b;
  b.da = 0.5 * n * a * std::abs(delta_roe[kDa]);
  b.de = 0.5 * n * a * std::hypot(delta_roe[kDex], delta_roe[kDey]);
  b.dlambda = dlambda_gauge(a * delta_roe[kDa], a * delta_roe[kDlambda], lever, n);
  b.dlambda_tangential = 0.5 * n * a * std::max(std::abs(delta_roe[kDa]), std::abs(delta_roe[kDa] + 2.0 * delta_roe[kDlambda] / lever));
  b.in_plane = std::max({b.da, b.de, b.dlambda});
  // The dlambda gauge includes lambda along da, so it is >= b.da up to the scan: the da case is
  // reported when the dlambda component adds nothing (relative 1e-9).
  if (b.de >= b.dlambda) {
    b.dominant = InPlaneCase::kDe;
  } else if (b.dlambda > b.da * (1.0 + 1e-9)) {
    b.dominant = InPlaneCase::kDlambda;
  } else {
    b.dominant = InPlaneCase::kDa;
  }

  // Out of plane (docs/algorithms/control.md#out-of-plane-bound-with-j2): a normal burn at t
  // changes di by the pre-image p = (w_ix, w_iy - k w_ix), k = 2 kappa sin^2 i (tf - t), because
  // dix drives diy by the differential nodal regression until tf. The cheapest burn time minimises ||p|| over
  // k in [0, k_max]; first order in kappa (tf - t).
  const double wix = delta_roe[kDix];
  const double wiy = delta_roe[kDiy];
  const double k_max = 2.0 * rates.kappa * si * si * window;
  double k_best = 0.0;
  if (wix != 0.0) k_best = std::clamp(wiy / wix, 0.0, k_max);
  b.out_of_plane = n * a * std::hypot(wix, wiy - k_best * wix);
  b.total = std::hypot(b.in_plane, b.out_of_plane);
  return b;
}

}  // namespace visors::control
