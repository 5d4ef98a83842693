#pragma once
// Test support: navigation solutions of a formation given by mean elements, advanced by the
// secular J2 model (astro::propagate_mean_j2) and converted to osculating Cartesian states, so
// the flight component sees the relative orbit it is meant to see (no noise). Maneuvers of the
// deputy can be applied (apply_deputy_dv), so a closed loop can run, and a constant differential
// along-track acceleration (set_differential_drag) in its secular effect on the mean elements.

#include <cmath>
#include <numbers>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/mean_osculating.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/gnc/messages.hpp"

namespace visors::gnc::test {

inline constexpr double kDeg = std::numbers::pi / 180.0;

/// The mission chief (DSC) mean elements (Guffanti et al., AAS 23-149, 2023, Table 5, u0 = 0;
/// argp 90 deg is this project's choice: docs/requirements.md#mission-timeline-and-orbits).
inline astro::KeplerianElements mission_chief() {
  return {6378136.3 + 500e3, 0.004, 97.8 * kDeg, 157.5 * kDeg, 90.0 * kDeg, -90.0 * kDeg};
}

class FormationHarness {
 public:
  FormationHarness(const astro::KeplerianElements& chief_mean, const Eigen::Matrix<double, 6, 1>& roe_m, core::GpsTime t0)
      : chief_(chief_mean), t0_(t0) {
    deputy_ = astro::deputy_from_roe(chief_mean, roe_m / chief_mean.a).value();
  }

  /// A constant along-track acceleration of the deputy, relative to the chief [m/s^2], through the
  /// Gauss variational equations of a near-circular orbit (D'Amico 2010, eq. 2.38, u = u0 + n tau,
  /// tau the time since the deputy's last impulse): a grows by 2 a_T tau / n; the mean argument of
  /// latitude falls behind by the integral of 1.5 n (a - a0) / a, 1.5 a_T tau^2 / a; the
  /// eccentricity vector (e cos w, e sin w) moves by 2 a_T / (n^2 a) (sin u - sin u0,
  /// cos u0 - cos u).
  void set_differential_drag(double a_t_mps2) { drag_mps2_ = a_t_mps2; }

  /// An impulse of the deputy at t_s, GCRF [m/s]: its mean elements restart from the new state.
  void apply_deputy_dv(double t_s, const Eigen::Vector3d& dv_gcrf) {
    core::StateVector x = state(deputy_mean(t_s));
    x.v += dv_gcrf;
    const auto osc = astro::cartesian_to_keplerian(x.r, x.v).value();
    deputy_ = astro::mean_from_osculating(osc).value();
    deputy_epoch_s_ = t_s;
  }

  [[nodiscard]] NavigationSolution navigation(double t_s) const {
    NavigationSolution out;
    out.t = t0_ + t_s;
    out.chief_gcrf = state(astro::propagate_mean_j2(chief_, t_s));
    out.deputy_gcrf = state(deputy_mean(t_s));
    out.relative_covariance_rtn.setZero();
    out.relative_covariance_rtn.diagonal() << 3.3e-5, 3.3e-5, 3.3e-5, 8.3e-10, 8.3e-10, 8.3e-10;  // 1 cm, 50 um/s 3D
    return out;
  }
  [[nodiscard]] GncInputs inputs(double t_s) const {
    GncInputs in;
    in.t = t0_ + t_s;
    in.time_at_tone = TimeAtTone{in.t, Eigen::Quaterniond::Identity()};
    in.navigation = navigation(t_s);
    return in;
  }
  [[nodiscard]] core::GpsTime t0() const { return t0_; }

  /// The true a * mean ROE at t_s [m].
  [[nodiscard]] Eigen::Matrix<double, 6, 1> roe_mean_m(double t_s) const {
    const astro::KeplerianElements chief = astro::propagate_mean_j2(chief_, t_s);
    return chief.a * astro::roe_from_keplerian(chief, deputy_mean(t_s)).value();
  }

 private:
  static core::StateVector state(const astro::KeplerianElements& mean) {
    return astro::cartesian_from_keplerian(astro::osculating_from_mean(mean).value(), core::EarthGravityConstants{}.mu);
  }

  astro::KeplerianElements deputy_mean(double t_s) const {
    const double tau = t_s - deputy_epoch_s_;
    astro::KeplerianElements m = astro::propagate_mean_j2(deputy_, tau);
    const double n = std::sqrt(core::EarthGravityConstants{}.mu / (deputy_.a * deputy_.a * deputy_.a));
    const double u0 = deputy_.argp + deputy_.M;
    const double u = m.argp + m.M;
    const double k = 2.0 * drag_mps2_ / (n * n * deputy_.a);
    const double ex = m.e * std::cos(m.argp) + k * (std::sin(u) - std::sin(u0));
    const double ey = m.e * std::sin(m.argp) + k * (std::cos(u0) - std::cos(u));
    m.a += 2.0 * drag_mps2_ * tau / n;
    m.e = std::hypot(ex, ey);
    m.argp = std::atan2(ey, ex);
    m.M = u - m.argp - 1.5 * drag_mps2_ * tau * tau / deputy_.a;  // the argument of latitude kept
    return m;
  }

  astro::KeplerianElements chief_, deputy_;
  double drag_mps2_ = 0.0;
  double deputy_epoch_s_ = 0.0;  // time of deputy_ since t0 [s]
  core::GpsTime t0_;
};

inline Eigen::Matrix<double, 6, 1> roe_m(double da, double dl, double dex, double dey, double dix, double diy) {
  Eigen::Matrix<double, 6, 1> r;
  r << da, dl, dex, dey, dix, diy;
  return r;
}

}  // namespace visors::gnc::test
