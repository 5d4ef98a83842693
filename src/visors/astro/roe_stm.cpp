#include "visors/astro/roe_stm.hpp"

#include <cmath>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/relative_orbital_elements.hpp"

namespace visors::astro {

RoeStm keplerian_roe_stm(const KeplerianElements& chief_mean, double tau, double mu) {
  const double n = std::sqrt(mu / (chief_mean.a * chief_mean.a * chief_mean.a));
  RoeStm phi = RoeStm::Identity();
  phi(roe::kDlambda, roe::kDa) = -1.5 * n * tau;
  return phi;
}

RoeStm j2_roe_stm(const KeplerianElements& chief_mean, double tau,
                  const core::EarthGravityConstants& gravity) {
  using namespace roe;
  const J2SecularRates rates = j2_secular_rates(chief_mean, gravity);
  const double e = chief_mean.e;
  const double eta2 = (1.0 - e) * (1.0 + e);
  const double eta = std::sqrt(eta2);
  const double kappa = rates.kappa;
  const double n = rates.n;
  const double c = std::cos(chief_mean.i);
  const double s = std::sin(chief_mean.i);
  // KGD17 eq. (A6) factors.
  const double E = 1.0 + eta;
  const double F = 4.0 + 3.0 * eta;
  const double G = 1.0 / eta2;
  const double P = 3.0 * c * c - 1.0;
  const double Q = 5.0 * c * c - 1.0;
  const double S = 2.0 * s * c;  // sin 2i
  const double T = s * s;        // sin^2 i
  const double wdot_tau = rates.argp_dot * tau;
  const double argp_f = chief_mean.argp + wdot_tau;
  const double exi = e * std::cos(chief_mean.argp);
  const double eyi = e * std::sin(chief_mean.argp);
  const double exf = e * std::cos(argp_f);
  const double eyf = e * std::sin(argp_f);
  const double cw = std::cos(wdot_tau);
  const double sw = std::sin(wdot_tau);
  const double kt = kappa * tau;

  RoeStm phi = RoeStm::Identity();
  phi(kDlambda, kDa) = -(1.5 * n + 3.5 * kappa * E * P) * tau;
  phi(kDlambda, kDex) = kt * exi * F * G * P;
  phi(kDlambda, kDey) = kt * eyi * F * G * P;
  phi(kDlambda, kDix) = -kt * F * S;

  phi(kDex, kDa) = 3.5 * kt * eyf * Q;
  phi(kDex, kDex) = cw - 4.0 * kt * exi * eyf * G * Q;
  phi(kDex, kDey) = -sw - 4.0 * kt * eyi * eyf * G * Q;
  phi(kDex, kDix) = 5.0 * kt * eyf * S;

  phi(kDey, kDa) = -3.5 * kt * exf * Q;
  phi(kDey, kDex) = sw + 4.0 * kt * exi * exf * G * Q;
  phi(kDey, kDey) = cw + 4.0 * kt * eyi * exf * G * Q;
  phi(kDey, kDix) = -5.0 * kt * exf * S;

  phi(kDiy, kDa) = 3.5 * kt * S;
  phi(kDiy, kDex) = -4.0 * kt * exi * G * S;
  phi(kDiy, kDey) = -4.0 * kt * eyi * G * S;
  phi(kDiy, kDix) = 2.0 * kt * T;
  return phi;
}

}  // namespace visors::astro
