#include "visors/safety/passive_safety.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/roe_rtn_map.hpp"
#include "visors/astro/roe_stm.hpp"
#include "visors/control/impulse_effect.hpp"

namespace visors::safety {
namespace {

using astro::RelativeOrbitalElements;

// Golden-section refinement stops when the bracket is shorter than this [s]. Near a minimum the
// separation is d0 + d'' dt^2 / 2 with d'' <~ n^2 |r| ~ 1e-4 m/s^2 at 100 m, so 1e-4 s is far
// below 1e-9 m.
constexpr double kTimeTolerance = 1e-4;
// Below this separation the direction r / |r| is undefined [m].
constexpr double kZeroSeparation = 1e-9;

struct Point {
  double separation = 0.0;  // [m]
  double sigma = 0.0;       // 1-sigma of the separation [m]
};

// The separation model of the header at one time, with everything fixed at t0.
class SeparationModel {
 public:
  SeparationModel(const astro::KeplerianElements& chief0, const RelativeOrbitalElements& roe0,
                  const RoeCovariance& p0, SafetyPlane plane, const core::EarthGravityConstants& g)
      : chief0_(chief0), roe0_(roe0), p0_(p0), plane_(plane), gravity_(g) {}

  [[nodiscard]] Point at(double t) const {
    const astro::KeplerianElements chief_t = astro::propagate_mean_j2(chief0_, t, gravity_);
    const astro::RoeStm phi = astro::j2_roe_stm(chief0_, t, gravity_);
    const astro::RoeToRtnMatrix map = astro::roe_to_rtn_matrix(chief_t, gravity_.mu, 0.0);
    // Position rows composed with the STM: r(t) = c * roe0.
    Eigen::Matrix<double, 3, 6> c = map.topRows<3>() * phi;
    if (plane_ == SafetyPlane::kRadialNormal) c.row(1).setZero();  // drop T
    const Eigen::Vector3d r = c * roe0_;
    Point out;
    out.separation = r.norm();
    if (out.separation > kZeroSeparation) {
      const Eigen::Matrix<double, 6, 1> h = c.transpose() * (r / out.separation);
      out.sigma = std::sqrt(std::max(0.0, h.dot(p0_ * h)));
    } else {
      const Eigen::Matrix3d sigma_r = c * p0_ * c.transpose();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(sigma_r, Eigen::EigenvaluesOnly);
      out.sigma = std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
    }
    return out;
  }

 private:
  astro::KeplerianElements chief0_;
  RelativeOrbitalElements roe0_;
  RoeCovariance p0_;
  SafetyPlane plane_;
  core::EarthGravityConstants gravity_;
};

// Golden-section minimisation of f on [lo, hi]; returns the argument and value of the best point
// seen (the endpoints are candidates too, so a monotonic f yields its endpoint minimum).
template <typename F>
void golden_section(const F& f, double lo, double hi, double f_lo, double f_hi, double& t_best,
                    double& f_best) {
  constexpr double kInvPhi = 0.6180339887498949;  // (sqrt(5) - 1) / 2
  t_best = f_lo <= f_hi ? lo : hi;
  f_best = std::min(f_lo, f_hi);
  double x1 = hi - kInvPhi * (hi - lo);
  double x2 = lo + kInvPhi * (hi - lo);
  double f1 = f(x1);
  double f2 = f(x2);
  while (hi - lo > kTimeTolerance) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kInvPhi * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kInvPhi * (hi - lo);
      f2 = f(x2);
    }
  }
  if (f1 < f_best) {
    f_best = f1;
    t_best = x1;
  }
  if (f2 < f_best) {
    f_best = f2;
    t_best = x2;
  }
}

// Streaming local-minimum finder over a uniform grid: feed samples in order; every grid local
// minimum (endpoints included) is refined on [t_{k-1}, t_{k+1}] and the global best is kept.
template <typename F>
class MinimumTracker {
 public:
  explicit MinimumTracker(const F& f) : f_(f) {}

  void push(double t, double value) {
    if (count_ >= 2 && value_prev_ <= value_prev2_ && value_prev_ <= value) {
      refine(t_prev2_, t, value_prev2_, value);
    } else if (count_ == 1 && value_prev_ <= value) {
      refine(t_prev_, t, value_prev_, value);  // minimum at the first sample
    }
    t_prev2_ = t_prev_;
    value_prev2_ = value_prev_;
    t_prev_ = t;
    value_prev_ = value;
    ++count_;
  }

  void finish() {
    if (count_ >= 2 && value_prev_ <= value_prev2_) refine(t_prev2_, t_prev_, value_prev2_, value_prev_);
    if (count_ == 1) keep(t_prev_, value_prev_);
  }

  [[nodiscard]] double t_best() const { return t_best_; }
  [[nodiscard]] double f_best() const { return f_best_; }

 private:
  void refine(double lo, double hi, double f_lo, double f_hi) {
    double t = 0.0;
    double v = 0.0;
    golden_section(f_, lo, hi, f_lo, f_hi, t, v);
    keep(t, v);
  }
  void keep(double t, double v) {
    if (!found_ || v < f_best_) {
      found_ = true;
      f_best_ = v;
      t_best_ = t;
    }
  }

  const F& f_;
  long count_ = 0;
  double t_prev_ = 0.0, t_prev2_ = 0.0, value_prev_ = 0.0, value_prev2_ = 0.0;
  bool found_ = false;
  double t_best_ = 0.0, f_best_ = 0.0;
};

bool finite_matrix(const RoeCovariance& p) { return p.allFinite(); }

}  // namespace

double rn_separation_closed_form(const RelativeOrbitalElements& roe, double a) {
  const Eigen::Vector2d de(roe[astro::roe::kDex], roe[astro::roe::kDey]);
  const Eigen::Vector2d di(roe[astro::roe::kDix], roe[astro::roe::kDiy]);
  const double s = de.squaredNorm() + di.squaredNorm();
  const double d = (de + di).norm() * (de - di).norm();
  if (s + d <= 0.0) return 0.0;
  return a * std::sqrt(2.0) * std::abs(de.dot(di)) / std::sqrt(s + d);
}

double orbital_period(const astro::KeplerianElements& chief, double mu) {
  return core::kTwoPi * std::sqrt(chief.a * chief.a * chief.a / mu);
}

core::Status validate_safety_inputs(const astro::KeplerianElements& chief_mean,
                                          const RelativeOrbitalElements& roe,
                                          const RoeCovariance& covariance,
                                          const core::EarthGravityConstants& gravity) {
  if (!(gravity.mu > 0.0) || !std::isfinite(gravity.mu)) return core::Status{core::Problem::kOutOfRange, "gravity.mu", "must be finite and > 0"};
  if (!(gravity.re > 0.0) || !std::isfinite(gravity.re)) return core::Status{core::Problem::kOutOfRange, "gravity.re", "must be finite and > 0"};
  if (!(gravity.j2 >= 0.0) || !std::isfinite(gravity.j2)) return core::Status{core::Problem::kOutOfRange, "gravity.j2", "must be finite and >= 0"};
  const auto chief = astro::validate_keplerian(chief_mean);
  if (!chief) return chief.status().within("chief");
  if (std::abs(std::sin(chief_mean.i)) < 1e-6) {
    return core::Status{core::Problem::kOutOfRange, "chief.i", "must not be equatorial (diy is undefined)"};
  }
  if (auto ok = control::validate_roe(roe, "roe"); !ok) return ok;
  if (!(roe[astro::roe::kDa] > -1.0)) return core::Status{core::Problem::kOutOfRange, "roe", "da must be > -1"};
  if (!finite_matrix(covariance)) return core::Status{core::Problem::kNotFinite, "covariance", "must be finite"};
  const double scale = covariance.cwiseAbs().maxCoeff();
  if ((covariance - covariance.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    return core::Status{core::Problem::kNotSymmetric, "covariance", "must be symmetric"};
  }
  if (scale > 0.0) {
    const Eigen::SelfAdjointEigenSolver<RoeCovariance> eig(covariance, Eigen::EigenvaluesOnly);
    if (eig.eigenvalues().minCoeff() < -1e-9 * eig.eigenvalues().maxCoeff()) {
      return core::Status{core::Problem::kOutOfRange, "covariance", "must be positive semidefinite"};
    }
  }
  return {};
}

core::Outcome<SafetyAssessment> evaluate_passive_safety(const astro::KeplerianElements& chief_mean,
                                                       const RelativeOrbitalElements& roe,
                                                       const RoeCovariance& covariance,
                                                       const PassiveSafetySettings& settings,
                                                       const core::EarthGravityConstants& gravity) {
  if (const core::Status checked = validate(settings); !checked) return checked;
  if (const core::Status inputs = validate_safety_inputs(chief_mean, roe, covariance, gravity); !inputs) return inputs;

  const SeparationModel model(chief_mean, roe, covariance, settings.plane, gravity);
  const double q = settings.q_sigma;
  const auto separation = [&model](double t) { return model.at(t).separation; };
  const auto margin = [&model, q](double t) {
    const Point p = model.at(t);
    return p.separation - q * p.sigma;
  };

  const double horizon = settings.horizon_orbits * orbital_period(chief_mean, gravity.mu);
  const double samples = std::ceil(settings.horizon_orbits * settings.samples_per_orbit);
  const long intervals = std::max(1L, static_cast<long>(samples));
  const double dt = horizon / static_cast<double>(intervals);

  MinimumTracker<decltype(separation)> nominal(separation);
  MinimumTracker<decltype(margin)> reduced(margin);
  for (long k = 0; k <= intervals; ++k) {
    const double t = k == intervals ? horizon : dt * static_cast<double>(k);
    const Point p = model.at(t);
    nominal.push(t, p.separation);
    reduced.push(t, p.separation - q * p.sigma);
  }
  nominal.finish();
  reduced.finish();

  SafetyAssessment out;
  out.min_separation_m = nominal.f_best();
  out.t_min_s = nominal.t_best();
  out.sigma_at_t_min_m = model.at(out.t_min_s).sigma;
  // The refined margin minimum can never exceed the margin at t_min (guards the case where the
  // margin's grid minimum lies in a different lobe than the separation's).
  out.min_separation_margin_m = reduced.f_best();
  out.t_min_margin_s = reduced.t_best();
  const double margin_at_t_min = out.min_separation_m - q * out.sigma_at_t_min_m;
  if (margin_at_t_min < out.min_separation_margin_m) {
    out.min_separation_margin_m = margin_at_t_min;
    out.t_min_margin_s = out.t_min_s;
  }
  out.safe = out.min_separation_margin_m >= settings.epsilon_m;
  return out;
}

}  // namespace visors::safety
