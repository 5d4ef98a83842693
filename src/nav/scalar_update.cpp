#include "nav/scalar_update.hpp"

#include <cmath>

namespace visors::nav {

namespace {

// P <- (P + P')/2 in place over the strict lower triangle: the rank-one updates leave round-off
// asymmetry, and the next update reads P h' as (h P)'.
void symmetrise(NavMatrix& P) {
  for (int j = 0; j < kNavStates; ++j) {
    for (int i = j + 1; i < kNavStates; ++i) {
      const double mean = 0.5 * (P(i, j) + P(j, i));
      P(i, j) = mean;
      P(j, i) = mean;
    }
  }
}

// The Joseph update given u = P h' (overwritten): header equations M = P - k u',
// w = u - (h u) k, P+ = M - (w - r k) k'.
void joseph_rank_one(NavMatrix& P, const NavRow& h, const NavVector& k, double r, NavVector& u) {
  const double hu = (h * u).value();
  P.noalias() -= k * u.transpose();  // M = (I - k h) P
  u -= (hu + r) * k;                 // w - r k = (I - k h) P h' - r k
  P.noalias() -= u * k.transpose();  // M (I - k h)' + k r k'
  symmetrise(P);
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
  u.noalias() = P * h.transpose();
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
