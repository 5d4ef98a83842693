#include "visors/astro/mean_osculating.hpp"

#include <algorithm>
#include <cmath>

#include "visors/astro/kepler_equation.hpp"
#include "visors/astro/quasi_nonsingular_elements.hpp"
#include "visors/core/angles.hpp"

namespace visors::astro {
namespace {

constexpr double kMaxEccentricity = 0.9;
constexpr double kMinSinInclination = 1e-6;
constexpr double kMinCriticalDistance = 1e-3;  // |1 - 5 cos^2 i|

core::Outcome<KeplerianElements> check(const KeplerianElements& el) {
  auto valid = validate_keplerian(el);
  if (!valid) return valid;
  if (el.e > kMaxEccentricity) return core::Status{core::Problem::kOutOfRange, "e", "must be <= 0.9 for the first-order J2 map"};
  if (std::sin(el.i) < kMinSinInclination) {
    return core::Status{core::Problem::kSingular, "i", "must not be equatorial (the J2 map is singular at i = 0, pi)"};
  }
  const double c2 = std::cos(el.i) * std::cos(el.i);
  if (std::abs(1.0 - 5.0 * c2) < kMinCriticalDistance) {
    return core::Status{core::Problem::kOutOfRange, "i", "too close to the critical inclination (1 - 5 cos^2 i = 0)"};
  }
  return el;
}

// The quantities of the mean elements that the J2 corrections of Schaub & Junkins App. F share.
struct MapTerms {
  double a, e, i, w, mean_anom, f;  // mean elements, f the mean true anomaly
  double eta, eta2, eta3, eta6;     // eta = sqrt(1 - e^2) and its powers
  double gamma2, gamma2p;           // (F.1), (F.3)
  double c, c2, c4, s2, crit;       // cos i and its powers, sin^2 i, 1 - 5 cos^2 i
  double a_r, a_r3;                 // a/r (F.6) and its cube
  double cf, sf;                    // cos f, sin f
  double c2w2f, s2w2f, c2wf, s2wf, c2w3f, s2w3f, s2w, c2w;  // cos/sin(2w + kf), cos/sin 2w
  double eoc;                       // equation of the centre + e sin f
  double long_k, long_k2;           // the long-period factors with 1/(1 - 5 cos^2 i)
  double triple_c, triple_s;        // 3 cos(2w+2f) + 3e cos(2w+f) + e cos(2w+3f), sin alike
};

MapTerms map_terms(const KeplerianElements& m, const core::EarthGravityConstants& g) {
  MapTerms t{};
  t.a = m.a;
  t.e = m.e;
  t.i = m.i;
  t.w = m.argp;
  t.mean_anom = m.M;
  const double a = t.a, e = t.e, w = t.w;
  t.f = true_from_mean(t.mean_anom, e);
  const double f = t.f;
  t.eta2 = (1.0 - e) * (1.0 + e);
  t.eta = std::sqrt(t.eta2);
  t.eta3 = t.eta2 * t.eta;
  t.eta6 = t.eta3 * t.eta3;
  t.gamma2 = 0.5 * g.j2 * (g.re / a) * (g.re / a);  // (F.1)
  t.gamma2p = t.gamma2 / (t.eta2 * t.eta2);         // (F.3)
  t.c = std::cos(m.i);
  t.c2 = t.c * t.c;
  t.c4 = t.c2 * t.c2;
  t.s2 = 1.0 - t.c2;
  t.crit = 1.0 - 5.0 * t.c2;
  t.a_r = (1.0 + e * std::cos(f)) / t.eta2;  // a/r (F.6)
  t.a_r3 = t.a_r * t.a_r * t.a_r;
  t.cf = std::cos(f);
  t.sf = std::sin(f);
  t.c2w2f = std::cos(2.0 * w + 2.0 * f);
  t.s2w2f = std::sin(2.0 * w + 2.0 * f);
  t.c2wf = std::cos(2.0 * w + f);
  t.s2wf = std::sin(2.0 * w + f);
  t.c2w3f = std::cos(2.0 * w + 3.0 * f);
  t.s2w3f = std::sin(2.0 * w + 3.0 * f);
  t.s2w = std::sin(2.0 * w);
  t.c2w = std::cos(2.0 * w);
  t.eoc = f - t.mean_anom + e * t.sf;
  t.long_k = 1.0 - 11.0 * t.c2 - 40.0 * t.c4 / t.crit;
  t.long_k2 = 11.0 + 80.0 * t.c2 / t.crit + 200.0 * t.c4 / (t.crit * t.crit);
  t.triple_c = 3.0 * t.c2w2f + 3.0 * e * t.c2wf + e * t.c2w3f;
  t.triple_s = 3.0 * t.s2w2f + 3.0 * e * t.s2wf + e * t.s2w3f;
  return t;
}

// (F.7): the osculating semi-major axis.
double osculating_semi_major_axis(const MapTerms& t) {
  return t.a + t.a * t.gamma2 *
                   ((3.0 * t.c2 - 1.0) * (t.a_r3 - 1.0 / t.eta3) + 3.0 * t.s2 * t.a_r3 * t.c2w2f);
}

// (F.8): the long-period part of de.
double long_period_de(const MapTerms& t) { return t.gamma2p / 8.0 * t.e * t.eta2 * t.long_k * t.c2w; }

// (F.9): de, long- plus short-period.
double eccentricity_change(const MapTerms& t, double de1) {
  const double e = t.e, cf = t.cf;
  const double cubic = 3.0 * cf + 3.0 * e * cf * cf + e * e * cf * cf * cf;
  return de1 + t.eta2 / 2.0 *
                   (t.gamma2 * ((3.0 * t.c2 - 1.0) / t.eta6 * (e * t.eta + e / (1.0 + t.eta) + cubic) +
                                3.0 * t.s2 / t.eta6 * (e + cubic) * t.c2w2f) -
                    t.gamma2p * t.s2 * (3.0 * t.c2wf + t.c2w3f));
}

// (F.10): di.
double inclination_change(const MapTerms& t, double de1) {
  return -t.e * de1 / (t.eta2 * std::tan(t.i)) + t.gamma2p / 2.0 * t.c * std::sqrt(t.s2) * t.triple_c;
}

// (F.13): dRAAN.
double node_change(const MapTerms& t) {
  return -t.gamma2p / 8.0 * t.e * t.e * t.c * t.long_k2 * t.s2w - t.gamma2p / 2.0 * t.c * (6.0 * t.eoc - t.triple_s);
}

// (F.12): the short-period factor X of dl and e dM.
double short_period_x(const MapTerms& t) {
  const double ar_eta2 = (t.a_r * t.eta) * (t.a_r * t.eta);
  return 2.0 * (3.0 * t.c2 - 1.0) * (ar_eta2 + t.a_r + 1.0) * t.sf +
         3.0 * t.s2 * ((-ar_eta2 - t.a_r + 1.0) * t.s2wf + (ar_eta2 + t.a_r + 1.0 / 3.0) * t.s2w3f);
}

// (F.12): e dM.
double e_dm(const MapTerms& t, double x_sp) {
  return t.gamma2p / 8.0 * t.e * t.eta3 * t.long_k * t.s2w - t.gamma2p / 4.0 * t.eta3 * x_sp;
}

// (F.11): the change of M + argp + RAAN, PLUS the term gamma2' e eta^2 x_sp / (4 (1 + eta)).
// That term is the O(e) remainder of the 1/e cancellation between Brouwer's short-period dl
// (= -gamma2' eta^3 x_sp / (4 e), F.12) and dg (+gamma2' eta^2 x_sp / (4 e) + regular terms);
// F.11 as printed (and as transcribed in Basilisk's clMeanOscMap) omits it. Found because the
// mean u along a numerically integrated J2 orbit kept an O(e J2) periodic residual (33 urad at
// e = 0.1, scaling linearly with J2); confirmed by evaluating dl + dg as partial derivatives of
// Brouwer's first-order generating function W1, which reproduces F.7, F.9, F.12, F.13 exactly.
double mean_longitude_change(const MapTerms& t, double x_sp, double d_raan) {
  const double e = t.e, c2 = t.c2, c4 = t.c4, crit = t.crit, gamma2p = t.gamma2p;
  return gamma2p * e * t.eta2 * x_sp / (4.0 * (1.0 + t.eta)) + gamma2p / 8.0 * t.eta3 * t.long_k * t.s2w -
         gamma2p / 16.0 *
             (2.0 + e * e - 11.0 * (2.0 + 3.0 * e * e) * c2 - 40.0 * (2.0 + 5.0 * e * e) * c4 / crit -
              400.0 * e * e * c4 * c2 / (crit * crit)) *
             t.s2w +
         gamma2p / 4.0 * (-6.0 * crit * t.eoc + (3.0 - 5.0 * c2) * t.triple_s) + d_raan;
}

// The first-order J2 changes of the mean elements (Lyddane's form).
struct J2Changes {
  double a_osc;   // osculating a (F.7)
  double de;      // (F.9)
  double di;      // (F.10)
  double d_raan;  // (F.13)
  double e_dm;    // e dM (F.12)
  double d_l;     // d(M + argp + RAAN) (F.11, completed)
};

// (F.14)-(F.22): the osculating elements reassembled, with M_osc, u_osc and RAAN_osc kept on the
// revolution of the mean ones.
QuasiNonsingularElements reassemble(const KeplerianElements& m, const J2Changes& d) {
  const double e = m.e;
  const double mean_anom = m.M;
  const double sm = std::sin(mean_anom);
  const double cm = std::cos(mean_anom);
  const double d1 = (e + d.de) * sm + d.e_dm * cm;
  const double d2 = (e + d.de) * cm - d.e_dm * sm;
  const double e_osc = std::hypot(d1, d2);
  const double m_osc = mean_anom + core::wrap_pi(std::atan2(d1, d2) - mean_anom);
  const double sh = std::sin(m.i / 2.0);
  const double ch = std::cos(m.i / 2.0);
  const double so = std::sin(m.raan);
  const double co = std::cos(m.raan);
  const double d3 = (sh + ch * d.di / 2.0) * so + sh * d.d_raan * co;
  const double d4 = (sh + ch * d.di / 2.0) * co - sh * d.d_raan * so;
  const double raan_osc = m.raan + core::wrap_pi(std::atan2(d3, d4) - m.raan);
  const double i_osc = 2.0 * std::asin(std::min(1.0, std::hypot(d3, d4)));
  const double l_osc = mean_anom + m.argp + m.raan + d.d_l;
  const double u_osc = l_osc - raan_osc;
  const double w_osc = u_osc - m_osc;
  return QuasiNonsingularElements{d.a_osc, u_osc, e_osc * std::cos(w_osc), e_osc * std::sin(w_osc), i_osc, raan_osc};
}

// Schaub & Junkins App. F, mean -> osculating (gamma2 > 0), returned in quasi-nonsingular form.
// The osculating u and RAAN are kept on the revolution of the mean ones.
QuasiNonsingularElements map_mean_to_osculating(const KeplerianElements& m,
                                                const core::EarthGravityConstants& g) {
  const MapTerms t = map_terms(m, g);
  J2Changes d{};
  d.a_osc = osculating_semi_major_axis(t);
  const double de1 = long_period_de(t);
  d.de = eccentricity_change(t, de1);
  d.di = inclination_change(t, de1);
  d.d_raan = node_change(t);
  const double x_sp = short_period_x(t);
  d.e_dm = e_dm(t, x_sp);
  d.d_l = mean_longitude_change(t, x_sp, d.d_raan);
  return reassemble(m, d);
}

}  // namespace

core::Outcome<KeplerianElements> osculating_from_mean(const KeplerianElements& mean,
                                                     const core::EarthGravityConstants& gravity) {
  auto checked = check(mean);
  if (!checked) return checked.status();
  KeplerianElements osc = keplerian_from_quasi_nonsingular(map_mean_to_osculating(mean, gravity));
  osc.M = core::wrap_two_pi(osc.M);
  osc.argp = core::wrap_two_pi(osc.argp);
  osc.raan = core::wrap_two_pi(osc.raan);
  return osc;
}

core::Outcome<KeplerianElements> mean_from_osculating(const KeplerianElements& osculating,
                                                     const core::EarthGravityConstants& gravity) {
  auto checked = check(osculating);
  if (!checked) return checked.status();
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
  return core::Status{core::Problem::kNotConverged, "osculating", "osculating -> mean iteration did not converge"};
}

}  // namespace visors::astro
