#include "visors/control/least_squares_planner.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "visors/astro/roe_stm.hpp"
#include "visors/control/closed_form_planner.hpp"
#include "visors/control/impulse_effect.hpp"

namespace visors::control {

core::Result<LeastSquaresPlan> plan_least_squares(const astro::KeplerianElements& chief_mean_t0,
                                                  const astro::RelativeOrbitalElements& roe0,
                                                  const astro::RelativeOrbitalElements& roe_target, double tf,
                                                  std::span<const double> burn_times,
                                                  const LeastSquaresSettings& settings,
                                                  const core::EarthGravityConstants& gravity) {
  LeastSquaresPlan out;
  out.plan.impulses.reserve(std::max<std::size_t>(burn_times.size(), 1));
  if (auto ok = plan_least_squares_into(out, chief_mean_t0, roe0, roe_target, tf, burn_times, settings, gravity); !ok) {
    return ok.error();
  }
  return out;
}

core::Status plan_least_squares_into(LeastSquaresPlan& out, const astro::KeplerianElements& chief_mean_t0,
                                           const astro::RelativeOrbitalElements& roe0,
                                           const astro::RelativeOrbitalElements& roe_target, double tf,
                                           std::span<const double> burn_times, const LeastSquaresSettings& settings,
                                           const core::EarthGravityConstants& gravity) {
  if (auto ok = validate_planner_chief(chief_mean_t0, "chief_mean_t0", gravity); !ok) return ok;
  if (auto ok = validate_roe(roe0, "roe0"); !ok) return ok;
  if (auto ok = validate_roe(roe_target, "roe_target"); !ok) return ok;
  if (!std::isfinite(tf) || tf <= 0.0) return core::Status{core::Problem::kOutOfRange, "tf", "must be finite and positive"};
  if (burn_times.empty() || burn_times.size() > static_cast<std::size_t>(kMaxLeastSquaresBurns)) {
    return core::Status{core::Problem::kOutOfRange, "burn_times", "must hold 1 to 6 times"};
  }
  for (std::size_t k = 0; k < burn_times.size(); ++k) {
    const double t = burn_times[k];
    if (!std::isfinite(t) || t < 0.0 || t > tf || (k > 0 && t < burn_times[k - 1])) {
      return core::Status{core::Problem::kOutOfRange, "burn_times", "every time must be finite, non-decreasing, in [0, tf]"};
    }
  }
  if (!std::isfinite(settings.relative_regularisation) || settings.relative_regularisation < 0.0) {
    return core::Status{core::Problem::kOutOfRange, "settings.relative_regularisation", "must be finite and >= 0"};
  }
  if (!std::isfinite(settings.min_reciprocal_condition) || settings.min_reciprocal_condition <= 0.0) {
    return core::Status{core::Problem::kOutOfRange, "settings.min_reciprocal_condition", "must be finite and positive"};
  }

  const double a = chief_mean_t0.a;
  const int m = static_cast<int>(burn_times.size());
  using Stack = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 3 * kMaxLeastSquaresBurns>;
  Stack big_m(6, 3 * m);
  for (int k = 0; k < m; ++k) {
    big_m.middleCols<3>(3 * k) = a * impulse_effect(chief_mean_t0, burn_times[static_cast<std::size_t>(k)], tf, gravity);
  }
  const Eigen::Matrix<double, 6, 1> w = a * (roe_target - astro::j2_roe_stm(chief_mean_t0, tf, gravity) * roe0);

  Eigen::Matrix<double, 6, 6> mmt = big_m * big_m.transpose();
  const double nu = settings.relative_regularisation * mmt.trace() / 6.0;
  if (nu == 0.0) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(mmt, Eigen::EigenvaluesOnly);
    const double lmax = eig.eigenvalues().maxCoeff();
    if (!(lmax > 0.0) || eig.eigenvalues().minCoeff() < settings.min_reciprocal_condition * lmax) {
      return core::Status{core::Problem::kSingular, "burn_times", "singular geometry: the impulses at these times do not span the six ROE "
                        "(use nu > 0 or spread the times, not all a multiple of pi apart in u)"};
    }
  }
  mmt.diagonal().array() += nu;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(mmt);
  const Eigen::Matrix<double, 6, 1> y = ldlt.solve(w);
  if (ldlt.info() != Eigen::Success || !y.allFinite()) {
    return core::Status{core::Problem::kSingular, "burn_times", "singular geometry: M M' + nu I could not be factorised"};
  }
  const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3 * kMaxLeastSquaresBurns, 1> v = big_m.transpose() * y;

  out.nu = nu;
  out.plan.impulses.clear();
  out.plan.dv_lower_bound_mps = 0.0;
  for (int k = 0; k < m; ++k) {
    out.plan.impulses.push_back(Impulse{burn_times[static_cast<std::size_t>(k)], v.segment<3>(3 * k)});
  }
  out.plan.dv_total_mps = total_delta_v(out.plan.impulses);
  out.plan.roe_final_predicted = predict_roe(chief_mean_t0, roe0, out.plan.impulses, tf, gravity);
  out.terminal_error = roe_target - out.plan.roe_final_predicted;
  return {};
}

}  // namespace visors::control
