#include "visors/control/stochastic_mpc.hpp"
#include "visors/control/impulse_effect.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Dense>

#include "visors/astro/roe_stm.hpp"

namespace visors::control {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

core::Error invalid(std::string field, std::string message) {
  return core::Error{std::move(field), std::move(message)};
}

bool symmetric_psd(const Matrix6d& m, bool strictly) {
  if (!m.allFinite()) return false;
  const double scale = std::max(m.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  if ((m - m.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) return false;
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(0.5 * (m + m.transpose()), Eigen::EigenvaluesOnly);
  const double min_eig = eig.eigenvalues().minCoeff();
  return strictly ? min_eig > 0.0 : min_eig >= -1e-12 * scale;
}

}  // namespace

StochasticMpc::StochasticMpc(const StochasticMpcSettings& settings, ReachableSetPlanner planner)
    : settings_(settings), planner_(std::move(planner)) {
  const auto capacity = static_cast<std::size_t>(std::max(settings.planner.max_impulses, 1));
  plan_.impulses.reserve(capacity);
  fresh_.impulses.reserve(capacity);
}

core::Result<StochasticMpc> StochasticMpc::create(const StochasticMpcSettings& s) {
  if (!(s.mahalanobis_threshold > 0.0) || !std::isfinite(s.mahalanobis_threshold)) {
    return invalid("mahalanobis_threshold", "must be finite and > 0");
  }
  if (!(s.execution_sigma_fraction >= 0.0) || !std::isfinite(s.execution_sigma_fraction)) {
    return invalid("execution_sigma_fraction", "must be finite and >= 0");
  }
  if (!(s.execution_sigma_floor_mps >= 0.0) || !std::isfinite(s.execution_sigma_floor_mps)) {
    return invalid("execution_sigma_floor_mps", "must be finite and >= 0");
  }
  if (!symmetric_psd(s.terminal_process_noise, false)) {
    return invalid("terminal_process_noise", "must be finite, symmetric and positive semidefinite");
  }
  if (!(s.freeze_time_s >= 0.0) || !std::isfinite(s.freeze_time_s)) return invalid("freeze_time_s", "must be finite and >= 0");
  if (!(s.burn_latency_s >= 0.0) || !std::isfinite(s.burn_latency_s)) return invalid("burn_latency_s", "must be finite and >= 0");
  auto planner = ReachableSetPlanner::create(s.planner);
  if (!planner.ok()) return invalid("planner." + planner.error().field, planner.error().message);
  return StochasticMpc(s, std::move(planner).value());
}

core::Status StochasticMpc::set_target(const astro::RelativeOrbitalElements& roe_target, double tf) {
  if (auto ok = validate_roe(roe_target, "roe_target"); !ok) return ok;
  if (!std::isfinite(tf)) return core::Status{core::Problem::kNotFinite, "tf"};
  target_ = roe_target;
  tf_ = tf;
  has_target_ = true;
  has_plan_ = false;
  plan_.impulses.clear();  // keeps its capacity
  return {};
}

core::Result<MpcStep> StochasticMpc::step(double t, const astro::KeplerianElements& chief_mean_t,
                                          const astro::RelativeOrbitalElements& roe_estimate,
                                          const Matrix6d& covariance) {
  MpcStep out;
  if (auto ok = step_into(out, t, chief_mean_t, roe_estimate, covariance); !ok) return ok.error();
  return out;
}

core::Status StochasticMpc::step_into(MpcStep& out, double t, const astro::KeplerianElements& chief_mean_t,
                                            const astro::RelativeOrbitalElements& roe_estimate,
                                            const Matrix6d& covariance,
                                            const astro::RelativeOrbitalElements& drift_tf) {
  if (!has_target_) return core::Status{core::Problem::kNotReady, "target", "set_target() was not called"};
  if (!std::isfinite(t) || t < last_t_ || t > tf_) return core::Status{core::Problem::kOutOfRange, "t", "must be finite, non-decreasing and <= tf"};
  if (const core::Status ok = astro::validate_keplerian(chief_mean_t).status(); !ok) return ok.within("chief_mean_t");
  if (auto ok = validate_roe(roe_estimate, "roe_estimate"); !ok) return ok;
  if (!symmetric_psd(covariance, true)) return core::Status{core::Problem::kOutOfRange, "covariance", "must be finite, symmetric and positive definite"};
  if (auto ok = validate_roe(drift_tf, "drift_tf"); !ok) return ok;
  last_t_ = t;

  const core::EarthGravityConstants& gravity = settings_.planner.gravity;
  const double tau = tf_ - t;

  // Executed impulses (t_j < t) leave the plan.
  std::erase_if(plan_.impulses, [t](const Impulse& imp) { return imp.t < t; });

  // Predicted terminal state and covariance with the remaining impulses.
  auto predict = [&](Eigen::Matrix<double, 6, 1>& mean, Matrix6d& cov) {
    const astro::RoeStm phi = astro::j2_roe_stm(chief_mean_t, tau, gravity);
    mean = phi * roe_estimate + drift_tf;
    cov = phi * covariance * phi.transpose() + settings_.terminal_process_noise;
    for (const Impulse& imp : plan_.impulses) {
      const Eigen::Matrix<double, 6, 3> b = impulse_effect(chief_mean_t, imp.t - t, tau, gravity);
      mean += b * imp.dv_rtn;
      const double sigma = settings_.execution_sigma_fraction * imp.dv_rtn.norm() + settings_.execution_sigma_floor_mps;
      cov += (sigma * sigma) * (b * b.transpose());
    }
  };

  out.replanned = false;
  Eigen::Matrix<double, 6, 1> mean;
  Matrix6d cov;
  predict(mean, cov);
  if (has_plan_) {
    const Eigen::LLT<Matrix6d> llt(cov);
    if (llt.info() != Eigen::Success) return core::Status{core::Problem::kSingular, "covariance", "predicted terminal covariance is not positive definite"};
    const Eigen::Matrix<double, 6, 1> err = mean - target_;
    out.mahalanobis = std::sqrt(err.dot(llt.solve(err)));
  } else {
    out.mahalanobis = std::numeric_limits<double>::infinity();
  }

  const bool frozen = tau < settings_.freeze_time_s;
  if ((!has_plan_ || out.mahalanobis > settings_.mahalanobis_threshold) && !frozen) {
    const double t_earliest = std::min(settings_.burn_latency_s, tau);
    // Into the spare plan, swapped in on success (the previous plan stays on failure); both keep
    // their reserved capacity, so replanning allocates nothing.
    const astro::RelativeOrbitalElements aim = target_ - drift_tf;
    if (auto ok = planner_.plan_into(fresh_, chief_mean_t, roe_estimate, aim, t_earliest, tau); !ok) return ok;
    std::swap(plan_, fresh_);
    for (Impulse& imp : plan_.impulses) imp.t += t;
    has_plan_ = true;
    ++replans_;
    out.replanned = true;
    predict(mean, cov);
  }
  out.remaining.assign(plan_.impulses.begin(), plan_.impulses.end());
  out.roe_final_predicted = mean;
  return {};
}

}  // namespace visors::control
