#include "visors/astro/kepler_equation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "visors/core/angles.hpp"
#include "visors/core/constants.hpp"

namespace visors::astro {
namespace {

// Solves on the reduced range M in [0, pi], where the root is bracketed by [M, min(M + e, pi)]
// (E - M = e sin E is in [0, e] there). Newton steps are safeguarded by bisection, so the
// iteration converges for every e < 1 including the hard corner e -> 1, M -> 0, where the
// derivative 1 - e cos E is tiny. The residual is evaluated as (1 - e) E + e (E - sin E) near
// E = 0 so that it keeps full relative precision when M is tiny.
double solve_reduced(double m, double e) {
  if (m == 0.0 || e == 0.0) return m;
  double lo = m;
  double hi = std::min(m + e, core::kPi);
  // Starter of Danby-type: E0 = M + 0.85 e (clamped into the bracket); for small M with high e
  // the cubic estimate E ~ (6 M / e)^(1/3) is better.
  double x = std::clamp(m + 0.85 * e, lo, hi);
  if (e > 0.8 && m < 0.2) x = std::clamp(std::cbrt(6.0 * m / e), lo, hi);
  const auto residual = [m, e](double ecc) {
    if (ecc < 0.1) {
      // E - sin E by its series (relative error < 1e-17 for E < 0.1)
      const double e2 = ecc * ecc;
      const double e_minus_sin =
          ecc * e2 / 6.0 * (1.0 - e2 / 20.0 * (1.0 - e2 / 42.0 * (1.0 - e2 / 72.0 * (1.0 - e2 / 110.0))));
      return (1.0 - e) * ecc + e * e_minus_sin - m;
    }
    return ecc - e * std::sin(ecc) - m;
  };
  for (int iter = 0; iter < 100; ++iter) {
    const double f = residual(x);
    if (f == 0.0) return x;
    if (f > 0.0) {
      hi = x;
    } else {
      lo = x;
    }
    const double fp = 1.0 - e * std::cos(x);
    double next = x - f / fp;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 4.0 * std::numeric_limits<double>::epsilon() * x) {
      return next;
    }
    x = next;
  }
  return x;
}

}  // namespace

double eccentric_from_mean(double mean_anomaly, double e) {
  // Reduce to (-pi, pi], use the odd symmetry, and add the periodic offset E - M back onto the
  // caller's M so that its revolution count is preserved.
  // (wrap only when needed: wrap_pi adds pi, which would cost a tiny M its relative precision)
  const double m_red = std::abs(mean_anomaly) <= core::kPi ? mean_anomaly : core::wrap_pi(mean_anomaly);
  const double sign = m_red < 0.0 ? -1.0 : 1.0;
  const double e_red = sign * solve_reduced(std::abs(m_red), e);
  return mean_anomaly + (e_red - m_red);
}

core::Outcome<double> solve_kepler(double mean_anomaly, double e) {
  if (!std::isfinite(e) || e < 0.0 || e >= 1.0) return core::Status{core::Problem::kOutOfRange, "e", "must be in [0, 1)"};
  if (!std::isfinite(mean_anomaly)) return core::Status{core::Problem::kNotFinite, "M", "must be finite"};
  return eccentric_from_mean(mean_anomaly, e);
}

double mean_from_eccentric(double eccentric_anomaly, double e) {
  return eccentric_anomaly - e * std::sin(eccentric_anomaly);
}

// nu - E = 2 atan(beta sin E / (1 - beta cos E)) with beta = e / (1 + sqrt(1 - e^2)): the
// half-angle relation tan(nu/2) = sqrt((1+e)/(1-e)) tan(E/2) rewritten without the branch cut at
// E = pi (e.g. Broucke & Cefola 1973 form); it keeps the revolution count of E.
double true_from_eccentric(double eccentric_anomaly, double e) {
  const double beta = e / (1.0 + std::sqrt((1.0 - e) * (1.0 + e)));
  return eccentric_anomaly +
         2.0 * std::atan2(beta * std::sin(eccentric_anomaly), 1.0 - beta * std::cos(eccentric_anomaly));
}

double eccentric_from_true(double true_anomaly, double e) {
  const double beta = e / (1.0 + std::sqrt((1.0 - e) * (1.0 + e)));
  return true_anomaly -
         2.0 * std::atan2(beta * std::sin(true_anomaly), 1.0 + beta * std::cos(true_anomaly));
}

double true_from_mean(double mean_anomaly, double e) {
  return true_from_eccentric(eccentric_from_mean(mean_anomaly, e), e);
}

double mean_from_true(double true_anomaly, double e) {
  return mean_from_eccentric(eccentric_from_true(true_anomaly, e), e);
}

}  // namespace visors::astro
