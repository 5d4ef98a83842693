#include "visors/astro/j2_secular.hpp"

#include <cmath>

namespace visors::astro {

J2SecularRates j2_secular_rates(const KeplerianElements& mean,
                                const core::EarthGravityConstants& gravity) {
  const double eta2 = (1.0 - mean.e) * (1.0 + mean.e);
  const double eta = std::sqrt(eta2);
  const double n = std::sqrt(gravity.mu / (mean.a * mean.a * mean.a));
  // kappa = (3/4) n J2 (R/p)^2 with p = a eta^2; identical to KGD17's (3/4) J2 R^2 sqrt(mu) /
  // (a^(7/2) eta^4).
  const double ratio = gravity.re / mean.a;
  const double kappa = 0.75 * n * gravity.j2 * ratio * ratio / (eta2 * eta2);
  const double c = std::cos(mean.i);
  const double c2 = c * c;
  J2SecularRates rates;
  rates.n = n;
  rates.kappa = kappa;
  rates.raan_dot = -2.0 * kappa * c;
  rates.argp_dot = kappa * (5.0 * c2 - 1.0);
  rates.M_dot = n + kappa * eta * (3.0 * c2 - 1.0);
  return rates;
}

KeplerianElements propagate_mean_j2(const KeplerianElements& mean, double dt,
                                    const core::EarthGravityConstants& gravity) {
  const J2SecularRates rates = j2_secular_rates(mean, gravity);
  KeplerianElements out = mean;
  out.raan += rates.raan_dot * dt;
  out.argp += rates.argp_dot * dt;
  out.M += rates.M_dot * dt;
  return out;
}

KeplerianElements propagate_kepler(const KeplerianElements& elements, double dt, double mu) {
  KeplerianElements out = elements;
  out.M += std::sqrt(mu / (elements.a * elements.a * elements.a)) * dt;
  return out;
}

}  // namespace visors::astro
