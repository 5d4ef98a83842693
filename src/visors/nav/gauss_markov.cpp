#include "visors/nav/gauss_markov.hpp"

#include <cassert>
#include <cmath>

namespace visors::nav {
namespace {

// Below this x = dt / tau the cancelling h_ij are summed as series, from it on as closed forms.
// Both lose accuracy towards the switch (the series' terms grow like (2x)^n / n!, the closed forms
// cancel as x falls); 1.5 minimised the worst error over x in [1, 5] among 1, 1.25, 1.5, 1.75, 2
// (6.4, 4.1, 1.9, 2.0, 3.4 e-15 relative; measured in double against 80-digit decimal).
constexpr double kSeriesLimit = 1.5;
// Last power summed: the first neglected term of the slowest series (h_rr / x^5, terms
// ~ (2x)^n / (2 n!)) is ~2e-21 of its sum at x = 1.5; the results stop changing from 28 on.
// A fixed count keeps the run time fixed.
constexpr int kLastTerm = 32;

// Sum over n = n0 .. kLastTerm of (-1)^(n - n0) (gamma 2^(n-1) - alpha n - beta) x^(n - n0) / n!:
// h(x) / x^n0 for the h_ij of the header, whose Taylor coefficients have this form because each
// h_ij is a polynomial plus multiples of e^-x, x e^-x and e^-2x. Terms are added from the largest
// (x < 1.5: they shrink after the first few).
double series(double x, int n0, double gamma, double alpha, double beta) {
  double f = 1.0;  // x^(n - n0) / n!
  for (int k = 2; k <= n0; ++k) f /= k;
  double p = std::ldexp(1.0, n0 - 1);  // 2^(n-1), exact
  double sign = 1.0;
  double sum = 0.0;
  for (int n = n0; n <= kLastTerm; ++n) {
    sum += sign * (gamma * p - alpha * n - beta) * f;
    f *= x / (n + 1);
    p *= 2.0;
    sign = -sign;
  }
  return sum;
}

// Phi = [[1, dt, tau^2 (x - 1 + E1)], [0, 1, tau (1 - E1)], [0, 0, E1]] (header). Phi_ra cancels
// like the Q terms (relative error eps / x in closed form): x - 1 + e^-x = x^2 sum_{n>=2}
// (-1)^n x^(n-2) / n! below kSeriesLimit (gamma = 0, beta = -1 in series()).
Eigen::Matrix3d transition(double dt, double tau, double x, double one_minus_e1, double e1) {
  const double phi_ra = x < kSeriesLimit ? dt * dt * series(x, 2, 0.0, 0.0, -1.0)
                                         : tau * (dt - tau * one_minus_e1);
  Eigen::Matrix3d phi;
  phi << 1.0, dt, phi_ra,
         0.0, 1.0, tau * one_minus_e1,
         0.0, 0.0, e1;
  return phi;
}

}  // namespace

GaussMarkovChain gauss_markov_chain(double dt, double tau, double sigma) {
  assert(dt > 0.0 && std::isfinite(dt));
  assert(tau > 0.0 && std::isfinite(tau));
  assert(sigma >= 0.0 && std::isfinite(sigma));
  const double x = dt / tau;
  const double e1 = std::exp(-x);
  const double m = -std::expm1(-x);        // 1 - E1, accurate for small x
  const double m2 = -std::expm1(-2.0 * x);  // 1 - E2
  const double s2 = sigma * sigma;
  const double q = 2.0 * s2 / tau;  // PSD of w [m^2/s^5]

  double rr = 0.0, rv = 0.0, ra = 0.0, vv = 0.0;
  if (x < kSeriesLimit) {
    // Q_ij = q tau^(1+k_i+k_j) h_ij(x) = q dt^(n0) (h_ij(x) / x^n0), n0 = 1 + k_i + k_j: powers of
    // dt, the smaller of dt and tau here. (alpha, beta) from the closed forms of the header.
    const double dt2 = dt * dt;
    rr = q * dt2 * dt2 * dt * series(x, 5, 1.0, 2.0, 0.0);
    rv = q * dt2 * dt2 * series(x, 4, 1.0, 1.0, 1.0);
    ra = q * dt2 * dt * series(x, 3, 1.0, 1.0, 0.0);
    vv = q * dt2 * dt * series(x, 3, 1.0, 0.0, 2.0);
  } else {
    // Q_ij = 2 sigma^2 tau^(k_i+k_j) h_ij(x) (q tau = 2 sigma^2): powers of tau < dt here.
    const double t2 = tau * tau;
    rr = 2.0 * s2 * t2 * t2 * (x * x * (x / 3.0 - 1.0) + x * (2.0 * m - 1.0) + 0.5 * m2);
    rv = 2.0 * s2 * t2 * tau * (x * (0.5 * x - m) + m - 0.5 * m2);
    ra = 2.0 * s2 * t2 * (0.5 * m2 - x * e1);
    vv = 2.0 * s2 * t2 * (x - 2.0 * m + 0.5 * m2);
  }
  const double va = s2 * tau * m * m;  // q tau^2 (1 - E1)^2 / 2, no cancellation
  const double aa = s2 * m2;           // sigma^2 (1 - E2)

  GaussMarkovChain chain;
  chain.transition = transition(dt, tau, x, m, e1);
  chain.noise << rr, rv, ra,
                 rv, vv, va,
                 ra, va, aa;
  return chain;
}

double white_equivalent_factor(double interval_s, double tau_s) {
  assert(interval_s > 0.0 && tau_s > 0.0);
  const double one_minus_phi = -std::expm1(-interval_s / tau_s);  // accurate for tau >> interval
  return (2.0 - one_minus_phi) / one_minus_phi;
}

core::Status check_gauss_markov(double tau, double sigma) {
  // Written so that NaN fails the comparisons.
  if (!(tau > 0.0) || !std::isfinite(tau)) {
    return core::Status{core::Problem::kOutOfRange, "empirical_tau_s", "must be a finite correlation time > 0 s"};
  }
  if (!(sigma >= 0.0) || !std::isfinite(sigma)) {
    return core::Status{core::Problem::kOutOfRange, "empirical_sigma_mps2", "must be a finite standard deviation >= 0 m/s^2"};
  }
  return {};
}

}  // namespace visors::nav
