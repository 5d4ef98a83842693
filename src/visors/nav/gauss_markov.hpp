#pragma once
// Discrete-time transition and process noise of the empirical-acceleration chain of the navigation
// filter (docs/algorithms/cdgps-filter.md#empirical-accelerations), one axis:
//
//   r' = v,  v' = a,  a' = -a / tau + w,  w white with PSD q = 2 sigma^2 / tau,
//
// a first-order Gauss-Markov acceleration (sigma: its steady-state standard deviation [m/s^2],
// tau: its correlation time [s]) integrated twice. Over a step dt, with x = dt / tau:
//
//   Phi = [[1, dt, tau^2 (x - 1 + e^-x)], [0, 1, tau (1 - e^-x)], [0, 0, e^-x]],
//   Q   = integral_0^dt Phi(s) e3 q e3' Phi(s)' ds   (the standard discretisation of the white noise;
//         Van Loan 1978, IEEE TAC 23(3):395-404, evaluates it as a block matrix exponential),
//
// whose column Phi(s) e3 = tau^k g_k(s / tau), g_a = e^-u, g_v = 1 - e^-u, g_r = u - 1 + e^-u
// (k = 0, 1, 2), so Q_ij = q tau^(1 + k_i + k_j) h_ij(x) with h_ij(x) = integral_0^x g_i g_j du:
//
//   h_aa = (1 - E2) / 2                     h_va = (1 - E1)^2 / 2
//   h_vv = x - 2 (1 - E1) + (1 - E2) / 2    h_ra = (1 - E2) / 2 - x E1
//   h_rv = x^2/2 - x (1 - E1) + (1 - E1) - (1 - E2) / 2
//   h_rr = x^3/3 - x^2 + x (1 - 2 E1) + (1 - E2) / 2,        E1 = e^-x, E2 = e^-2x.
//
// These are the closed forms of the integrated first-order Gauss-Markov chain of dynamic model
// compensation (Tapley, Schutz & Born 2004, Statistical Orbit Determination, ch. 4), derived in
// docs/algorithms/cdgps-filter.md#empirical-accelerations; h_va, usually written
// (1 - E1) - (1 - E2)/2, is rewritten here with 1 - E2 = (1 - E1)(1 + E1).
//
// Numerical evaluation (why: the closed forms of h_vv, h_ra, h_rv, h_rr and Phi_ra cancel
// catastrophically for small x; h_rr loses about log10(40 / x^4) digits, all of them at x = 1e-4,
// and Phi_ra = tau dt - tau^2 (1 - E1) loses log10(2 / x)):
// - 1 - E1 and 1 - E2 are formed with expm1; h_aa, h_va and Phi_va then need nothing else;
// - below x = 1.5, h_vv, h_ra, h_rv, h_rr and Phi_ra are summed as their Taylor series in x, exact
//   coefficients (-1)^(n-n0) (2^(n-1) - alpha n - beta) / n! (Phi_ra / tau^2: (-1)^n / n!), n from
//   the leading power n0 to 32 (truncation ~2e-21 relative at x = 1.5); not a leading-order
//   approximation;
// - from x = 1.5 on, the closed forms above, which lose at most ~10 ulp there and less beyond.
// Accuracy, measured in double against 80-digit decimal arithmetic of the closed forms at 3000
// random x (log-uniform in [1e-8, 100]) and 1001 x evenly in [1, 5]: every h_ij and Phi_ra / tau^2
// within 1.9e-15 relative. The assembled Q and Phi agree per element with Van Loan's method in
// 200-digit arithmetic (tests/nav/test_gauss_markov.cpp, dt = 10 s, dt/tau = 1e-8 .. 100) to
// 4.2e-16 (Q) and 2.2e-16 (Phi), except Phi_aa = e^-x at dt/tau = 100: 5.5e-15, which is the
// rounding of x = dt / tau times the condition number x of e^-x (the input's limit, not the
// method's).
// The series branch is scaled by powers of dt and the closed-form branch by powers of tau, the
// smaller of the two in each, so that neither underflows nor overflows for tiny or large x.


#include <Eigen/Core>

#include "visors/core/status.hpp"

namespace visors::nav {

struct GaussMarkovChain {      // per axis: position, velocity, Gauss-Markov acceleration
  Eigen::Matrix3d transition;  // Phi over dt, states (r [m], v [m/s], a [m/s^2])
  Eigen::Matrix3d noise;       // Q over dt, same states, symmetric positive definite (zero if sigma = 0)
};

/// dt > 0 [s], tau > 0 [s], sigma >= 0 [m/s^2]; the caller validated them (debug asserts).
/// Relative accuracy ~1e-15 per element for every dt / tau in [1e-8, 100] (header comment).
GaussMarkovChain gauss_markov_chain(double dt, double tau, double sigma);

/// Variance factor of a first-order Gauss-Markov error sampled every interval_s (> 0) with
/// correlation time tau_s (> 0), phi = exp(-interval / tau): (1 + phi) / (1 - phi). The mean of
/// N >> tau / interval samples has the variance of N / factor independent ones (Bartlett's
/// formula for an AR(1) sequence: 1 + 2 sum_k phi^k), so weighing each sample with its variance
/// times this factor makes a long run of them worth what it is. 1 as tau -> 0; 2 tau / interval
/// for tau >> interval.
double white_equivalent_factor(double interval_s, double tau_s);

/// Validation at the configuration boundary: tau finite and > 0, sigma finite and >= 0; the error
/// names the field ("empirical_tau_s", "empirical_sigma_mps2"); ok when both are valid.
core::Status check_gauss_markov(double tau, double sigma);

}  // namespace visors::nav
