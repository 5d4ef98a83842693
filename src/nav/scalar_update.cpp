#include "nav/scalar_update.hpp"

#include <cmath>

namespace visors::nav {

namespace {

// The Joseph update given u = P h': with w = u - (h u) k, the header's
//   P+ = (P - k u') - (w - r k) k' = P - k u' - v k',  v = u - (h u + r) k,
// i.e. P+ = P - (k u' + u k' - c k k'), c = h u + r: a symmetric rank-two change. P is taken as
// symmetric (every producer keeps it exactly so): its lower triangle is updated column by column
// (contiguous, so the compiler vectorises it) and mirrored, which keeps P+ exactly symmetric
// against the round-off (the next update reads P h' as (h P)'). Reading both mirror images per
// element, as before, made the pass strided: 1.4x slower in the filter's epoch.
void joseph_rank_one(NavMatrix& P, const NavRow& h, const NavVector& k, double r, const NavVector& u) {
  const double c = (h * u).value() + r;
  for (int j = 0; j < kNavStates; ++j) {
    const int n = kNavStates - j;
    const double a = u(j) - c * k(j);
    P.col(j).tail(n) -= k.tail(n) * a + u.tail(n) * k(j);
  }
  P.triangularView<Eigen::StrictlyUpper>() = P.transpose();
}

// u = P h' over the non-zero entries of h only: a GPS scalar touches ~20 of the 74 states
// (positions, clocks, phase centres, one or two ambiguities), so the product is a sum of ~20
// columns of P instead of the whole matrix-vector product.
void sparse_product(const NavMatrix& P, const NavRow& h, NavVector& u) {
  u.setZero();
  for (int i = 0; i < kNavStates; ++i) {
    if (h(i) != 0.0) u.noalias() += P.col(i) * h(i);
  }
}

bool finite_scalars(double innovation, double variance, double gate_sigmas) {
  return std::isfinite(innovation) && std::isfinite(variance) && std::isfinite(gate_sigmas);
}

}  // namespace

std::string_view to_string(ScalarUpdateStatus status) {
  switch (status) {
    case ScalarUpdateStatus::kAccepted: return "accepted";
    case ScalarUpdateStatus::kRejected: return "rejected";
    case ScalarUpdateStatus::kInvalid: return "invalid";
  }
  return "unknown";
}

bool joseph_update(NavMatrix& P, const NavRow& h, const NavVector& gain, double variance, NavVector& workspace) {
  if (!std::isfinite(variance) || variance < 0.0 || !h.allFinite() || !gain.allFinite()) return false;
  workspace.noalias() = P * h.transpose();
  // A NaN or infinity anywhere in P reaches u: Inf * 0 and NaN * 0 are NaN.
  if (!workspace.allFinite()) return false;
  joseph_rank_one(P, h, gain, variance, workspace);
  return true;
}

ScalarUpdateResult scalar_update(NavVector& x, NavMatrix& P, const NavRow& h, double innovation, double variance,
                                 double gate_sigmas, ScalarUpdateWorkspace& workspace) {
  ScalarUpdateResult result;
  result.innovation = innovation;
  if (!finite_scalars(innovation, variance, gate_sigmas) || !(variance > 0.0) || !(gate_sigmas > 0.0) ||
      !h.allFinite() || !x.allFinite()) {
    return result;
  }
  NavVector& u = workspace.ph;
  sparse_product(P, h, u);
  if (!u.allFinite()) return result;  // a non-finite P (see joseph_update)
  const double s = (h * u).value() + variance;
  if (!std::isfinite(s) || !(s > 0.0)) return result;  // P not positive semidefinite along h
  result.innovation_variance = s;
  result.normalised_innovation = innovation / std::sqrt(s);
  result.normalised_innovation_squared = innovation * innovation / s;
  if (std::abs(innovation) > gate_sigmas * std::sqrt(s)) {
    result.status = ScalarUpdateStatus::kRejected;
    return result;
  }
  NavVector& k = workspace.gain;
  k = u / s;
  if (!k.allFinite()) return result;  // overflow of a finite input (s subnormal)
  x.noalias() += k * innovation;
  joseph_rank_one(P, h, k, variance, u);
  result.status = ScalarUpdateStatus::kAccepted;
  return result;
}

}  // namespace visors::nav
