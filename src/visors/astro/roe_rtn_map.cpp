#include "visors/astro/roe_rtn_map.hpp"

#include <cmath>

#include <Eigen/LU>

#include "visors/astro/kepler_equation.hpp"

namespace visors::astro {
namespace {

// Keplerian drift of the ROE over tau: only dlambda moves, by -1.5 n tau da (mean ROE; exact
// within first order for any e).
RoeToRtnMatrix keplerian_drift(double n, double tau) {
  RoeToRtnMatrix phi = RoeToRtnMatrix::Identity();
  phi(roe::kDlambda, roe::kDa) = -1.5 * n * tau;
  return phi;
}

}  // namespace

RoeToRtnMatrix roe_to_rtn_matrix(const KeplerianElements& chief, double mu, double tau) {
  const double a = chief.a;
  const double e = chief.e;
  const double n = std::sqrt(mu / (a * a * a));
  const double eta2 = (1.0 - e) * (1.0 + e);
  const double eta = std::sqrt(eta2);
  const double eta3 = eta2 * eta;
  const double nu = true_from_mean(chief.M, e);
  const double k = 1.0 + e * std::cos(nu);
  const double kp = -e * std::sin(nu);
  const double theta = chief.argp + nu;
  const double ct = std::cos(theta);
  const double st = std::sin(theta);
  const double ex = e * std::cos(chief.argp);
  const double ey = e * std::sin(chief.argp);
  const double cot_i = std::cos(chief.i) / std::sin(chief.i);
  const double ope = 1.0 + eta;
  const double k2 = k * k;

  // Sullivan, Grimberg & D'Amico 2017 form, scale factors a eta^2 and a n / eta
  // (docs/algorithms/relative-motion.md#eccentric-roe-to-rtn-map), checked entry by entry against
  // a finite-difference Jacobian of the exact elements -> Cartesian -> RTN map
  // (tests/astro/test_roe_rtn_map.cpp). The T-velocity entries of dex and dey are the time
  // derivative of the T-position entries (theta' = n k^2/eta^3, dk/dt = n k^2 k'/eta^3, ROE
  // constant); the expansion "(1 + k^2/eta^3) cos(theta) + (e_x/k^2)(...)" found in some
  // transcriptions agrees only to O(e^2) (error 0.3 of the entry at e = 0.3, 1e-4 at e = 0.01).
  Eigen::Matrix<double, 3, 6> br;
  br << 1.0 / k, -kp / eta3, (ex * (k - 1.0) / ope - ct) / eta3, (ey * (k - 1.0) / ope - st) / eta3,
      0.0, kp * cot_i / eta3,
      //
      0.0, k / eta3, ((1.0 + 1.0 / k) * st + ey / k + (k / eta) * ey / ope) / eta2,
      -((1.0 + 1.0 / k) * ct + ex / k + (k / eta) * ex / ope) / eta2, 0.0,
      (1.0 / k - k / eta3) * cot_i,
      //
      0.0, 0.0, 0.0, 0.0, st / k, -ct / k;
  Eigen::Matrix<double, 3, 6> bv;
  bv << kp / 2.0, k2 * (k - 1.0) / eta3, (k2 / eta3) * (eta * st + ey * (k - 1.0) / ope),
      -(k2 / eta3) * (eta * ct + ex * (k - 1.0) / ope), 0.0, -(k2 / eta3) * (k - 1.0) * cot_i,
      //
      -1.5 * k, k2 * kp / eta3,
      (k2 / eta2) * (1.0 + 1.0 / k) * ct - kp * (st + ey) / eta2 + k2 * kp * ey / (eta3 * ope),
      (k2 / eta2) * (1.0 + 1.0 / k) * st + kp * (ct + ex) / eta2 - k2 * kp * ex / (eta3 * ope), 0.0,
      -(1.0 + k2 / eta3) * kp * cot_i,
      //
      0.0, 0.0, 0.0, 0.0, ct + ex, st + ey;

  RoeToRtnMatrix m;
  m.topRows<3>() = (a * eta2) * br;
  m.bottomRows<3>() = (a * n / eta) * bv;
  return m * keplerian_drift(n, tau);
}

RoeToRtnMatrix roe_to_rtn_matrix_near_circular(const KeplerianElements& chief, double mu,
                                               double tau) {
  const double a = chief.a;
  const double n = std::sqrt(mu / (a * a * a));
  const double u = chief.argp + chief.M;
  const double cu = std::cos(u);
  const double su = std::sin(u);
  // D'Amico (2010 thesis), e = 0 (docs/algorithms/relative-motion.md#near-circular-roe-to-rtn-map).
  RoeToRtnMatrix m;
  m << 1.0, 0.0, -cu, -su, 0.0, 0.0,  //
      0.0, 1.0, 2.0 * su, -2.0 * cu, 0.0, 0.0,  //
      0.0, 0.0, 0.0, 0.0, su, -cu,  //
      0.0, 0.0, su, -cu, 0.0, 0.0,  //
      -1.5, 0.0, 2.0 * cu, 2.0 * su, 0.0, 0.0,  //
      0.0, 0.0, 0.0, 0.0, cu, su;
  m.topRows<3>() *= a;
  m.bottomRows<3>() *= a * n;
  return m * keplerian_drift(n, tau);
}

RelativeRtnVector rtn_from_roe(const KeplerianElements& chief, const RelativeOrbitalElements& roe,
                              double mu, double tau) {
  return roe_to_rtn_matrix(chief, mu, tau) * roe;
}

RelativeOrbitalElements roe_from_rtn(const KeplerianElements& chief,
                                     const RelativeRtnVector& state_rtn, double mu, double tau) {
  return roe_to_rtn_matrix(chief, mu, tau).partialPivLu().solve(state_rtn);
}

RelativeRtnVector rtn_from_roe_near_circular(const KeplerianElements& chief,
                                            const RelativeOrbitalElements& roe, double mu,
                                            double tau) {
  return roe_to_rtn_matrix_near_circular(chief, mu, tau) * roe;
}

}  // namespace visors::astro
