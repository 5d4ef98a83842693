#include "nav/scalar_update.hpp"

#include <cmath>

namespace visors::nav {

namespace {

// The Joseph update given u = P h': with w = u - (h u) k, the header's
//   P+ = (P - k u') - (w - r k) k' = P - k u' - v k',  v = u - (h u + r) k,
// in one pass over the lower triangle, each element the mean of its two mirror images (the
// update is symmetric in exact arithmetic; averaging keeps P exactly symmetric against the
// round-off, and the next update reads P h' as (h P)'), then mirrored. Three passes over P
// before (two rank-one updates and a symmetrisation); 44 % of the replay's time went here.
void joseph_rank_one(NavMatrix& P, const NavRow& h, const NavVector& k, double r, const NavVector& u) {
  const NavVector v = u - ((h * u).value() + r) * k;
  for (int j = 0; j < kNavStates; ++j) {
    const double kj = k(j), uj = u(j), vj = v(j);
    for (int i = j; i < kNavStates; ++i) {
      P(i, j) = 0.5 * (P(i, j) + P(j, i)) - 0.5 * (k(i) * uj + kj * u(i) + v(i) * kj + vj * k(i));
    }
  }
  P.triangularView<Eigen::StrictlyUpper>() = P.transpose();
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
