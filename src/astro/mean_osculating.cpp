#include "astro/mean_osculating.hpp"

#include <algorithm>
#include <cmath>

#include "astro/kepler_equation.hpp"
#include "astro/quasi_nonsingular_elements.hpp"
#include "core/angles.hpp"

namespace visors::astro {
namespace {

constexpr double kMaxEccentricity = 0.9;
constexpr double kMinSinInclination = 1e-6;
constexpr double kMinCriticalDistance = 1e-3;  // |1 - 5 cos^2 i|

core::Result<KeplerianElements> check(const KeplerianElements& el) {
  auto valid = validate_keplerian(el);
  if (!valid) return valid;
  if (el.e > kMaxEccentricity) return core::Error{"e", "must be <= 0.9 for the first-order J2 map"};
  if (std::sin(el.i) < kMinSinInclination) {
    return core::Error{"i", "must not be equatorial (the J2 map is singular at i = 0, pi)"};
  }
  const double c2 = std::cos(el.i) * std::cos(el.i);
  if (std::abs(1.0 - 5.0 * c2) < kMinCriticalDistance) {
    return core::Error{"i", "too close to the critical inclination (1 - 5 cos^2 i = 0)"};
  }
  return el;
}

// Schaub & Junkins App. F, mean -> osculating (gamma2 > 0), returned in quasi-nonsingular form.
// The osculating u and RAAN are kept on the revolution of the mean ones.
QuasiNonsingularElements map_mean_to_osculating(const KeplerianElements& m,
                                                const core::EarthGravityConstants& g) {
  const double a = m.a;
  const double e = m.e;
  const double w = m.argp;
  const double mean_anom = m.M;
  const double f = true_from_mean(mean_anom, e);
  const double eta2 = (1.0 - e) * (1.0 + e);
  const double eta = std::sqrt(eta2);
  const double eta3 = eta2 * eta;
  const double eta6 = eta3 * eta3;
  const double gamma2 = 0.5 * g.j2 * (g.re / a) * (g.re / a);  // (F.1)
  const double gamma2p = gamma2 / (eta2 * eta2);               // (F.3)
  const double c = std::cos(m.i);
  const double c2 = c * c;
  const double c4 = c2 * c2;
  const double s2 = 1.0 - c2;
  const double crit = 1.0 - 5.0 * c2;
  const double a_r = (1.0 + e * std::cos(f)) / eta2;  // a/r (F.6)
  const double a_r3 = a_r * a_r * a_r;
  const double cf = std::cos(f);
  const double sf = std::sin(f);
  const double c2w2f = std::cos(2.0 * w + 2.0 * f);
  const double s2w2f = std::sin(2.0 * w + 2.0 * f);
  const double c2wf = std::cos(2.0 * w + f);
  const double s2wf = std::sin(2.0 * w + f);
  const double c2w3f = std::cos(2.0 * w + 3.0 * f);
  const double s2w3f = std::sin(2.0 * w + 3.0 * f);
  const double s2w = std::sin(2.0 * w);
  const double c2w = std::cos(2.0 * w);
  const double eoc = f - mean_anom + e * sf;  // equation of the centre + e sin f
  const double long_k = 1.0 - 11.0 * c2 - 40.0 * c4 / crit;
  const double long_k2 = 11.0 + 80.0 * c2 / crit + 200.0 * c4 / (crit * crit);

  // (F.7)
  const double a_osc = a + a * gamma2 * ((3.0 * c2 - 1.0) * (a_r3 - 1.0 / eta3) + 3.0 * s2 * a_r3 * c2w2f);
  // (F.8)
  const double de1 = gamma2p / 8.0 * e * eta2 * long_k * c2w;
  // (F.9)
  const double cubic = 3.0 * cf + 3.0 * e * cf * cf + e * e * cf * cf * cf;
  const double de = de1 + eta2 / 2.0 *
                              (gamma2 * ((3.0 * c2 - 1.0) / eta6 * (e * eta + e / (1.0 + eta) + cubic) +
                                         3.0 * s2 / eta6 * (e + cubic) * c2w2f) -
                               gamma2p * s2 * (3.0 * c2wf + c2w3f));
  // (F.10)
  const double triple_c = 3.0 * c2w2f + 3.0 * e * c2wf + e * c2w3f;
  const double triple_s = 3.0 * s2w2f + 3.0 * e * s2wf + e * s2w3f;
  const double di = -e * de1 / (eta2 * std::tan(m.i)) + gamma2p / 2.0 * c * std::sqrt(s2) * triple_c;
  // (F.13)
  const double d_raan = -gamma2p / 8.0 * e * e * c * long_k2 * s2w - gamma2p / 2.0 * c * (6.0 * eoc - triple_s);
  // (F.12)
  const double ar_eta2 = (a_r * eta) * (a_r * eta);
  const double x_sp = 2.0 * (3.0 * c2 - 1.0) * (ar_eta2 + a_r + 1.0) * sf +
                      3.0 * s2 * ((-ar_eta2 - a_r + 1.0) * s2wf + (ar_eta2 + a_r + 1.0 / 3.0) * s2w3f);
  const double e_dm = gamma2p / 8.0 * e * eta3 * long_k * s2w - gamma2p / 4.0 * eta3 * x_sp;
  // (F.11): the change of M + argp + RAAN, PLUS the term gamma2' e eta^2 x_sp / (4 (1 + eta)).
  // That term is the O(e) remainder of the 1/e cancellation between Brouwer's short-period dl
  // (= -gamma2' eta^3 x_sp / (4 e), F.12) and dg (+gamma2' eta^2 x_sp / (4 e) + regular terms);
  // F.11 as printed (and as transcribed in Basilisk's clMeanOscMap) omits it. Found because the
  // mean u along a numerically integrated J2 orbit kept an O(e J2) periodic residual (33 urad at
  // e = 0.1, scaling linearly with J2); confirmed by evaluating dl + dg as partial derivatives of
  // Brouwer's first-order generating function W1, which reproduces F.7, F.9, F.12, F.13 exactly.
  const double d_l = gamma2p * e * eta2 * x_sp / (4.0 * (1.0 + eta)) + gamma2p / 8.0 * eta3 * long_k * s2w -
                     gamma2p / 16.0 *
                         (2.0 + e * e - 11.0 * (2.0 + 3.0 * e * e) * c2 - 40.0 * (2.0 + 5.0 * e * e) * c4 / crit -
                          400.0 * e * e * c4 * c2 / (crit * crit)) *
                         s2w +
                     gamma2p / 4.0 * (-6.0 * crit * eoc + (3.0 - 5.0 * c2) * triple_s) + d_raan;
  // (F.14)-(F.22), with M_osc kept on the revolution of the mean M.
  const double sm = std::sin(mean_anom);
  const double cm = std::cos(mean_anom);
  const double d1 = (e + de) * sm + e_dm * cm;
  const double d2 = (e + de) * cm - e_dm * sm;
  const double e_osc = std::hypot(d1, d2);
  const double m_osc = mean_anom + core::wrap_pi(std::atan2(d1, d2) - mean_anom);
  const double sh = std::sin(m.i / 2.0);
  const double ch = std::cos(m.i / 2.0);
  const double so = std::sin(m.raan);
  const double co = std::cos(m.raan);
  const double d3 = (sh + ch * di / 2.0) * so + sh * d_raan * co;
  const double d4 = (sh + ch * di / 2.0) * co - sh * d_raan * so;
  const double raan_osc = m.raan + core::wrap_pi(std::atan2(d3, d4) - m.raan);
  const double i_osc = 2.0 * std::asin(std::min(1.0, std::hypot(d3, d4)));
  const double l_osc = mean_anom + w + m.raan + d_l;
  const double u_osc = l_osc - raan_osc;
  const double w_osc = u_osc - m_osc;

  return QuasiNonsingularElements{a_osc, u_osc, e_osc * std::cos(w_osc), e_osc * std::sin(w_osc),
                                  i_osc, raan_osc};
}

}  // namespace

core::Result<KeplerianElements> osculating_from_mean(const KeplerianElements& mean,
                                                     const core::EarthGravityConstants& gravity) {
  auto checked = check(mean);
  if (!checked) return checked.error();
  KeplerianElements osc = keplerian_from_quasi_nonsingular(map_mean_to_osculating(mean, gravity));
  osc.M = core::wrap_two_pi(osc.M);
  osc.argp = core::wrap_two_pi(osc.argp);
  osc.raan = core::wrap_two_pi(osc.raan);
  return osc;
}

core::Result<KeplerianElements> mean_from_osculating(const KeplerianElements& osculating,
                                                     const core::EarthGravityConstants& gravity) {
  auto checked = check(osculating);
  if (!checked) return checked.error();
  const QuasiNonsingularElements target = quasi_nonsingular_from_keplerian(osculating);
  // The map is the identity plus O(J2), so x <- x + (target - F(x)) contracts by O(J2) per step.
  QuasiNonsingularElements x = target;
  for (int iter = 0; iter < 50; ++iter) {
    const KeplerianElements x_kep = keplerian_from_quasi_nonsingular(x);
    if (x_kep.e >= kMaxEccentricity || std::sin(x.i) < kMinSinInclination) break;
    const QuasiNonsingularElements fx = map_mean_to_osculating(x_kep, gravity);
    const double da = target.a - fx.a;
    const double du = core::wrap_pi(target.u - fx.u);
    const double dex = target.ex - fx.ex;
    const double dey = target.ey - fx.ey;
    const double di = target.i - fx.i;
    const double draan = core::wrap_pi(target.raan - fx.raan);
    x.a += da;
    x.u += du;
    x.ex += dex;
    x.ey += dey;
    x.i += di;
    x.raan += draan;
    const double step = std::max({std::abs(da) / target.a, std::abs(du), std::abs(dex), std::abs(dey),
                                  std::abs(di), std::abs(draan)});
    if (step < 1e-14) {  // the last correction was below 1e-17: round-off level
      KeplerianElements mean = keplerian_from_quasi_nonsingular(x);
      mean.M = core::wrap_two_pi(mean.M);
      mean.argp = core::wrap_two_pi(mean.argp);
      mean.raan = core::wrap_two_pi(mean.raan);
      return mean;
    }
  }
  return core::Error{"osculating", "osculating -> mean iteration did not converge"};
}

}  // namespace visors::astro
