#include "visors/astro/keplerian_elements.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "visors/astro/kepler_equation.hpp"
#include "visors/core/angles.hpp"

namespace visors::astro {
namespace {

bool finite(const Eigen::Vector3d& x) { return x.allFinite(); }

}  // namespace

core::Outcome<KeplerianElements> validate_keplerian(const KeplerianElements& el) {
  if (!std::isfinite(el.a) || el.a <= 0.0) return core::Status{core::Problem::kOutOfRange, "a", "must be finite and > 0"};
  if (!std::isfinite(el.e) || el.e < 0.0 || el.e >= 1.0) {
    return core::Status{core::Problem::kOutOfRange, "e", "must be in [0, 1)"};
  }
  if (!std::isfinite(el.i) || el.i < 0.0 || el.i > core::kPi) {
    return core::Status{core::Problem::kOutOfRange, "i", "must be in [0, pi]"};
  }
  if (!std::isfinite(el.raan)) return core::Status{core::Problem::kNotFinite, "raan", "must be finite"};
  if (!std::isfinite(el.argp)) return core::Status{core::Problem::kNotFinite, "argp", "must be finite"};
  if (!std::isfinite(el.M)) return core::Status{core::Problem::kNotFinite, "M", "must be finite"};
  return el;
}

double true_anomaly(const KeplerianElements& el) { return true_from_mean(el.M, el.e); }

core::StateVector cartesian_from_keplerian(const KeplerianElements& el, double mu) {
  const double ecc_anomaly = eccentric_from_mean(el.M, el.e);
  const double cos_e = std::cos(ecc_anomaly);
  const double sin_e = std::sin(ecc_anomaly);
  const double eta = std::sqrt((1.0 - el.e) * (1.0 + el.e));
  const double r_norm = el.a * (1.0 - el.e * cos_e);
  // Perifocal components (e.g. Montenbruck & Gill 2000, eqs. 2.43-2.44).
  const double x_pf = el.a * (cos_e - el.e);
  const double y_pf = el.a * eta * sin_e;
  const double vel_scale = std::sqrt(mu * el.a) / r_norm;
  const double vx_pf = -vel_scale * sin_e;
  const double vy_pf = vel_scale * eta * cos_e;
  // Perifocal axes P, Q in the inertial frame: R3(-raan) R1(-i) R3(-argp).
  const double co = std::cos(el.raan), so = std::sin(el.raan);
  const double cw = std::cos(el.argp), sw = std::sin(el.argp);
  const double ci = std::cos(el.i), si = std::sin(el.i);
  const Eigen::Vector3d p{co * cw - so * sw * ci, so * cw + co * sw * ci, sw * si};
  const Eigen::Vector3d q{-co * sw - so * cw * ci, -so * sw + co * cw * ci, cw * si};
  return core::StateVector{x_pf * p + y_pf * q, vx_pf * p + vy_pf * q};
}

core::Outcome<core::StateVector> keplerian_to_cartesian(const KeplerianElements& elements, double mu) {
  if (!std::isfinite(mu) || mu <= 0.0) return core::Status{core::Problem::kOutOfRange, "mu", "must be finite and > 0"};
  auto checked = validate_keplerian(elements);
  if (!checked) return checked.status();
  return cartesian_from_keplerian(elements, mu);
}

core::Outcome<KeplerianElements> cartesian_to_keplerian(const Eigen::Vector3d& r,
                                                       const Eigen::Vector3d& v, double mu) {
  if (!std::isfinite(mu) || mu <= 0.0) return core::Status{core::Problem::kOutOfRange, "mu", "must be finite and > 0"};
  if (!finite(r)) return core::Status{core::Problem::kNotFinite, "r", "must be finite"};
  if (!finite(v)) return core::Status{core::Problem::kNotFinite, "v", "must be finite"};
  const double r_norm = r.norm();
  if (r_norm == 0.0) return core::Status{core::Problem::kOutOfRange, "r", "must be nonzero"};
  const Eigen::Vector3d h = r.cross(v);
  const double h_norm = h.norm();
  if (h_norm <= 1e-15 * r_norm * v.norm() || h_norm == 0.0) {
    return core::Status{core::Problem::kOutOfRange, "v", "rectilinear motion (zero angular momentum) has no Keplerian elements"};
  }
  const double inv_a = 2.0 / r_norm - v.squaredNorm() / mu;
  if (!(inv_a > 0.0)) {
    return core::Status{core::Problem::kOutOfRange, "v", "orbit is not elliptic (energy >= 0: parabolic or hyperbolic)"};
  }
  KeplerianElements el;
  el.a = 1.0 / inv_a;
  const Eigen::Vector3d h_hat = h / h_norm;
  const double h_xy = std::hypot(h.x(), h.y());
  el.i = std::atan2(h_xy, h.z());
  // Node line from h itself, so that n_hat is exactly orthogonal to h; angles in the plane are
  // then measured in the orthonormal in-plane basis (n_hat, m_hat = h_hat x n_hat), which stays
  // well conditioned however small the eccentricity or inclination is.
  Eigen::Vector3d n_hat{1.0, 0.0, 0.0};
  if (h_xy > kEquatorialTolerance * h_norm) {
    el.raan = std::atan2(h.x(), -h.y());
    n_hat = Eigen::Vector3d{std::cos(el.raan), std::sin(el.raan), 0.0};
  }
  const Eigen::Vector3d m_hat = h_hat.cross(n_hat);
  // Eccentricity vector (Laplace vector / mu).
  const Eigen::Vector3d e_vec = ((v.squaredNorm() - mu / r_norm) * r - r.dot(v) * v) / mu;
  const double e_n = e_vec.dot(n_hat);
  const double e_m = e_vec.dot(m_hat);
  el.e = std::hypot(e_n, e_m);  // in-plane part; the out-of-plane part is round-off only
  const double u_true = std::atan2(r.dot(m_hat), r.dot(n_hat));  // true argument of latitude
  double nu = 0.0;
  if (el.e < kCircularTolerance) {
    el.e = 0.0;
    el.argp = 0.0;
    nu = u_true;
  } else {
    el.argp = std::atan2(e_m, e_n);
    nu = u_true - el.argp;
  }
  if (el.e >= 1.0) return core::Status{core::Problem::kOutOfRange, "v", "orbit is not elliptic (e >= 1)"};
  el.M = core::wrap_two_pi(mean_from_true(core::wrap_pi(nu), el.e));
  el.raan = core::wrap_two_pi(el.raan);
  el.argp = core::wrap_two_pi(el.argp);
  return el;
}

}  // namespace visors::astro
