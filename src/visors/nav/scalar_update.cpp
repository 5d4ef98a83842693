#include "visors/nav/scalar_update.hpp"

#include <cmath>

namespace visors::nav {

namespace {

// The Joseph update given u = P h': with w = u - (h u) k, the header's
//   P+ = (P - k u') - (w - r k) k' = P - k u' - v k',  v = u - (h u + r) k,
// i.e. P+ = P - (k u' + u k' - c k k'), c = h u + r: a symmetric rank-two change, applied to the
// lower triangle only, column by column (contiguous, so the compiler vectorises it). The strict
// upper triangle is left as it was: see mirror_lower.
void joseph_rank_one_lower(NavMatrix& P, const NavRow& h, const NavVector& k, double r, const NavVector& u) {
  const double c = (h * u).value() + r;
  for (int j = 0; j < kNavStates; ++j) {
    const int n = kNavStates - j;
    const double a = u(j) - c * k(j);
    P.col(j).tail(n) -= k.tail(n) * a + u.tail(n) * k(j);
  }
}

// u = P h' over the non-zero entries of h only: a GPS scalar touches ~20 of the 98 states
// (positions, clocks, phase centres, one or two ambiguities), so the product is a sum of ~20
// columns of P instead of the whole matrix-vector product. Reads the lower triangle only: column
// i of the symmetric P is P(i:, i) below the diagonal and row P(i, :i) above it.
void sparse_product_lower(const NavMatrix& P, const NavRow& h, NavVector& u) {
  u.setZero();
  for (int i = 0; i < kNavStates; ++i) {
    if (h(i) == 0.0) continue;
    u.tail(kNavStates - i).noalias() += P.col(i).tail(kNavStates - i) * h(i);
    u.head(i).noalias() += P.row(i).head(i).transpose() * h(i);
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
  joseph_rank_one_lower(P, h, gain, variance, workspace);
  mirror_lower(P);
  return true;
}

ScalarUpdateResult scalar_update_lower(NavVector& x, NavMatrix& P, const NavRow& h, double innovation, double variance,
                                       double gate_sigmas, ScalarUpdateWorkspace& workspace) {
  return scalar_update_lower(x, P, h, innovation, variance, variance, gate_sigmas, workspace);
}

ScalarUpdateResult scalar_update_lower(NavVector& x, NavMatrix& P, const NavRow& h, double innovation, double variance,
                                       double gate_variance, double gate_sigmas, ScalarUpdateWorkspace& workspace) {
  ScalarUpdateResult result;
  result.innovation = innovation;
  if (!finite_scalars(innovation, variance, gate_sigmas) || !std::isfinite(gate_variance) || !(variance > 0.0) ||
      !(gate_variance > 0.0) || !(gate_sigmas > 0.0) || !h.allFinite() || !x.allFinite()) {
    return result;
  }
  NavVector& u = workspace.ph;
  sparse_product_lower(P, h, u);
  if (!u.allFinite()) return result;  // a non-finite P (see joseph_update)
  const double hph = (h * u).value();
  const double s = hph + variance;
  const double s_gate = hph + gate_variance;
  if (!std::isfinite(s) || !(s > 0.0) || !(s_gate > 0.0)) return result;  // P not positive semidefinite along h
  result.innovation_variance = s_gate;
  result.normalised_innovation = innovation / std::sqrt(s_gate);
  result.normalised_innovation_squared = innovation * innovation / s_gate;
  if (std::abs(innovation) > gate_sigmas * std::sqrt(s_gate)) {
    result.status = ScalarUpdateStatus::kRejected;
    return result;
  }
  NavVector& k = workspace.gain;
  k = (u / s).cwiseProduct(workspace.gain_mask);
  if (!k.allFinite()) return result;  // overflow of a finite input (s subnormal)
  x.noalias() += k * innovation;
  joseph_rank_one_lower(P, h, k, variance, u);
  result.status = ScalarUpdateStatus::kAccepted;
  return result;
}

ScalarUpdateResult scalar_update(NavVector& x, NavMatrix& P, const NavRow& h, double innovation, double variance,
                                 double gate_sigmas, ScalarUpdateWorkspace& workspace) {
  const ScalarUpdateResult result = scalar_update_lower(x, P, h, innovation, variance, gate_sigmas, workspace);
  if (result.status == ScalarUpdateStatus::kAccepted) mirror_lower(P);
  return result;
}

void mirror_lower(NavMatrix& P) { P.triangularView<Eigen::StrictlyUpper>() = P.transpose(); }

}  // namespace visors::nav
