#pragma once
// Sequential scalar measurement update of the navigation filter in Joseph form, with an innovation
// gate (docs/algorithms/cdgps-filter.md#sequential-scalar-updates). The measurement noise is
// diagonal (one scalar per GRAPHIC and per SDCP), so an epoch's measurements are processed one at
// a time: O(n^2) each, no matrix inverse, and every scalar gated on its own.
//
// For one scalar y = h x + v, v ~ N(0, r), innovation nu = y - h(x):
//   u = P h',  s = h u + r,  k = u / s,  x+ = x + k nu,
//   P+ = (I - k h) P (I - k h)' + k r k'   (Joseph; Bucy & Joseph 1968)
// The Joseph form is the covariance of the updated error for ANY gain k, a congruence of P plus a
// positive semidefinite term, so it stays symmetric positive semidefinite when k departs from the
// optimum (round-off in k, a gated or consider-state gain); the short form (I - k h) P equals it
// only for the optimal k and loses definiteness otherwise (tests/nav/test_scalar_update.cpp).
// Computed by rank-one updates in O(n^2), never forming I - k h nor a product of n x n matrices:
//   M  = (I - k h) P        = P - k u'          (h P = u' for a symmetric P)
//   w  = M h'               = u - (h u) k
//   P+ = M (I - k h)' + r k k' = M - (w - r k) k'
// as one symmetric rank-two change over the lower triangle, mirrored (exactly symmetric): about
// n^2 multiply-adds, and u over the non-zero entries of h only (~20 of 98 for a GPS scalar).
//
// Gate: the update is applied only when |nu| <= gate_sigmas sqrt(s) (4-5 sigmas; for the SDCP the
// cycle-slip detector, docs/algorithms/cdgps-filter.md#cycle-slips); otherwise x and P are
// untouched and the normalised innovation is reported. Invalid input (NaN or infinity in x, h, nu,
// r, gate_sigmas or the columns of P that h touches, r <= 0, gate_sigmas <= 0, s <= 0 from a P that
// is not positive semidefinite) is refused the same way: no NaN reaches x or P (one elsewhere in P
// stays where it is). Allocates nothing: the caller owns the workspace.

#include <string_view>

#include "visors/nav/navigation_state.hpp"

namespace visors::nav {

enum class ScalarUpdateStatus {
  kAccepted,  // x, P updated
  kRejected,  // innovation beyond the gate; x, P untouched
  kInvalid,   // input refused (see above); x, P untouched
};

/// "accepted", "rejected", "invalid".
std::string_view to_string(ScalarUpdateStatus status);

struct ScalarUpdateResult {
  ScalarUpdateStatus status = ScalarUpdateStatus::kInvalid;
  double innovation = 0.0;                     // nu, as given
  double innovation_variance = 0.0;            // s = h P h' + r (0 when not computed)
  double normalised_innovation = 0.0;          // nu / sqrt(s)
  double normalised_innovation_squared = 0.0;  // nu^2 / s: the NIS, chi-square(1) when consistent
};

/// Work vectors of scalar_update, preallocated by the caller (fixed size, 2 x 98 doubles).
struct ScalarUpdateWorkspace {
  NavVector ph;    // P h', then (I - k h) P h' - r k
  NavVector gain;  // k = P h' / s
  // 1: the state is estimated; 0: a consider state (Schmidt): its gain is zeroed, so its
  // estimate is held while its covariance and its correlations with the others are carried by
  // the Joseph form, which holds for any gain. All ones: the optimal update.
  NavVector gain_mask = NavVector::Ones();
};

/// One scalar update in place on (x, P): innovation nu = y - h(x) [measurement unit], h the
/// partials [measurement unit per state unit], variance r > 0 [measurement unit^2], gate in
/// sigmas of sqrt(s) (> 0, finite). P must be symmetric (the update reads P h' as (h P)').
ScalarUpdateResult scalar_update(NavVector& x, NavMatrix& P, const NavRow& h, double innovation, double variance,
                                 double gate_sigmas, ScalarUpdateWorkspace& workspace);

/// The same update reading and writing only the lower triangle of P (the strict upper triangle is
/// left stale), for a run of updates: mirror_lower(P) once after the run, before anything reads
/// the whole matrix. Mirroring after every scalar, as scalar_update does, is a strided pass over
/// half the matrix per scalar, which a run of updates saves (bench/bench_nav.cpp).
ScalarUpdateResult scalar_update_lower(NavVector& x, NavMatrix& P, const NavRow& h, double innovation, double variance,
                                       double gate_sigmas, ScalarUpdateWorkspace& workspace);

/// The same with the gate (and the reported innovation variance and NIS) on a variance of its own:
/// s_gate = h P h' + gate_variance, while the gain uses s = h P h' + variance. For a measurement
/// whose errors are correlated from epoch to epoch, the update weighs it by an inflated variance
/// (what N correlated samples are worth), while a slip still shows against the per-epoch noise
/// (nav/cdgps_settings.hpp, sdcp_correlation_inflation). gate_variance > 0, finite.
ScalarUpdateResult scalar_update_lower(NavVector& x, NavMatrix& P, const NavRow& h, double innovation, double variance,
                                       double gate_variance, double gate_sigmas, ScalarUpdateWorkspace& workspace);

/// Copies the lower triangle of P onto its upper one: P exactly symmetric.
void mirror_lower(NavMatrix& P);

/// The Joseph covariance update alone, for a given gain k (optimal or not):
/// P <- (I - k h) P (I - k h)' + k r k', by the rank-one updates above, symmetrised. False, with
/// P untouched, when h, k, r or P h' is not finite or r < 0. workspace: one caller-owned vector.
bool joseph_update(NavMatrix& P, const NavRow& h, const NavVector& gain, double variance, NavVector& workspace);

}  // namespace visors::nav
