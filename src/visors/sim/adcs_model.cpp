#include "visors/sim/adcs_model.hpp"

#include <cmath>
#include <string>
#include <utility>

namespace visors::sim {
namespace {

constexpr double kMaxSigmaRad = core::kDegToRad;  // an error beyond 1 deg is not an ADCS of this class

core::Result<bool> check_sigmas(const Eigen::Vector3d& sigma_rad, const char* field) {
  if (!sigma_rad.allFinite() || (sigma_rad.array() < 0.0).any() || (sigma_rad.array() > kMaxSigmaRad).any()) {
    return core::Error{field, "must be three finite numbers in [0, 3600] arcsec"};
  }
  return true;
}

core::Result<bool> check_time(double tau_s, const char* field) {
  if (!std::isfinite(tau_s) || tau_s < 0.0) return core::Error{field, "must be finite and >= 0 s"};
  return true;
}

// One first-order Gauss-Markov step of each axis over dt (tau = 0: a fresh white draw).
void gauss_markov_step(Eigen::Vector3d& x, const Eigen::Vector3d& sigma, double tau_s, double dt_s, bool first,
                       RandomStream& rng) {
  const double a = (first || tau_s <= 0.0) ? 0.0 : std::exp(-dt_s / tau_s);
  const double b = std::sqrt(1.0 - a * a);
  for (int k = 0; k < 3; ++k) x(k) = a * x(k) + b * rng.normal(sigma(k));
}

}  // namespace

core::Result<bool> AdcsSettings::validate() const {
  if (!std::isfinite(slew_rate_radps) || !(slew_rate_radps > 0.0)) {
    return core::Error{"slew_rate_deg_s", "must be a finite number > 0 deg/s"};
  }
  if (auto ok = check_sigmas(pointing_sigma_rad, "pointing_sigma_arcsec"); !ok) return ok;
  if (auto ok = check_time(pointing_tau_s, "pointing_tau_s"); !ok) return ok;
  if (auto ok = check_sigmas(jitter_sigma_rad, "jitter_sigma_arcsec"); !ok) return ok;
  if (auto ok = check_sigmas(knowledge_sigma_rad, "knowledge_sigma_arcsec"); !ok) return ok;
  return check_time(knowledge_tau_s, "knowledge_tau_s");
}

core::Result<AdcsModel> AdcsModel::create(const AdcsSettings& settings, RandomStream rng) {
  if (auto ok = settings.validate(); !ok) return ok.error();
  return AdcsModel(settings, std::move(rng));
}

void AdcsModel::step(double t_s) {
  const double dt_s = started_ ? t_s - t_s_ : 0.0;
  gauss_markov_step(pointing_rad_, settings_.pointing_sigma_rad, settings_.pointing_tau_s, dt_s, !started_, rng_);
  gauss_markov_step(jitter_rad_, settings_.jitter_sigma_rad, 0.0, dt_s, true, rng_);
  gauss_markov_step(knowledge_rad_, settings_.knowledge_sigma_rad, settings_.knowledge_tau_s, dt_s, !started_, rng_);
  t_s_ = t_s;
  started_ = true;
}

Eigen::Quaterniond AdcsModel::true_attitude(const Eigen::Quaterniond& q_commanded_body_to_gcrf) const {
  return (q_commanded_body_to_gcrf * rotation_quaternion(pointing_error_body_rad())).normalized();
}

Eigen::Quaterniond AdcsModel::reported_attitude(const Eigen::Quaterniond& q_true_body_to_gcrf) const {
  return (q_true_body_to_gcrf * rotation_quaternion(knowledge_rad_)).normalized();
}

Eigen::Quaterniond rotation_quaternion(const Eigen::Vector3d& theta_rad) {
  const double angle = theta_rad.norm();
  if (angle == 0.0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, theta_rad / angle));
}

}  // namespace visors::sim
