#include "visors/sim/propulsion.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Geometry>

namespace visors::sim {
namespace {

// Round-off allowance on the impulse spacing [s]: the project's time resolution (1 ns).
constexpr double kSpacingTolerance_s = 1.0e-9;

bool finite_positive(double x) { return std::isfinite(x) && x > 0.0; }

// Two unit vectors completing `unit` to a right-handed orthonormal basis (e1, e2, unit). The seed
// axis is the coordinate axis least aligned with `unit`, so the cross product is well conditioned.
std::pair<Eigen::Vector3d, Eigen::Vector3d> perpendicular_basis(const Eigen::Vector3d& unit) {
  Eigen::Index least = 0;
  unit.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d e1 = unit.cross(Eigen::Vector3d::Unit(least)).normalized();
  return {e1, unit.cross(e1)};
}

}  // namespace

core::Result<bool> PropulsionSettings::validate() const {
  if (!finite_positive(min_impulse_ns)) return core::Error{"min_impulse_ns", "must be a finite number > 0 N s"};
  if (!std::isfinite(max_impulse_ns) || max_impulse_ns < min_impulse_ns) {
    return core::Error{"max_impulse_ns", "must be finite and >= min_impulse_ns"};
  }
  if (!finite_positive(quantum_ns) || quantum_ns > min_impulse_ns) {
    return core::Error{"quantum_ns", "must be in (0, min_impulse_ns]"};
  }
  if (!(spacing_s >= 0.0) || !std::isfinite(spacing_s)) return core::Error{"spacing_s", "must be finite and >= 0 s"};
  if (!(magnitude_sigma >= 0.0 && magnitude_sigma <= 0.5)) return core::Error{"magnitude_sigma", "must be in [0, 0.5]"};
  if (!(magnitude_bias_sigma >= 0.0 && magnitude_bias_sigma <= 0.5)) {
    return core::Error{"magnitude_bias_sigma", "must be in [0, 0.5]"};
  }
  if (!(direction_sigma_rad >= 0.0 && direction_sigma_rad <= 10.0 * core::kDegToRad)) {
    return core::Error{"direction_sigma_rad", "must be in [0, 10 deg]"};
  }
  if (!finite_positive(isp_s)) return core::Error{"isp_s", "must be a finite number > 0 s"};
  if (!(isp_sigma_s >= 0.0) || !std::isfinite(isp_sigma_s)) return core::Error{"isp_sigma_s", "must be finite and >= 0 s"};
  return true;
}

Propulsion::Propulsion(const PropulsionSettings& settings, double wet_mass_kg, double propellant_kg, double isp_s,
                       RandomStream rng)
    : settings_(settings), mass_kg_(wet_mass_kg), propellant_kg_(propellant_kg), isp_s_(isp_s), rng_(std::move(rng)) {}

core::Result<Propulsion> Propulsion::create(const PropulsionSettings& settings, double wet_mass_kg,
                                            double propellant_kg, RandomStream rng) {
  if (auto ok = settings.validate(); !ok) return ok.error();
  if (!finite_positive(wet_mass_kg)) return core::Error{"wet_mass_kg", "must be a finite number > 0 kg"};
  if (!std::isfinite(propellant_kg) || propellant_kg < 0.0 || propellant_kg >= wet_mass_kg) {
    return core::Error{"propellant_kg", "must be finite and in [0, wet_mass_kg)"};
  }
  const double isp_true_s = settings.isp_s + rng.normal(settings.isp_sigma_s);  // drawn once per run
  if (!(isp_true_s > 0.0)) return core::Error{"isp_s", "drawn true specific impulse is not positive"};
  Propulsion propulsion(settings, wet_mass_kg, propellant_kg, isp_true_s, std::move(rng));
  // Clamped so that no nozzle pushes backwards (matters only for sigmas near 0.5).
  for (double& b : propulsion.nozzle_bias_) b = std::max(-1.0, propulsion.rng_.normal(settings.magnitude_bias_sigma));
  return propulsion;
}

// Step 2 of the file comment: J = m |dv| rounded to the quantum, kept within [min, max].
core::Result<double> Propulsion::quantised_impulse_ns(const Eigen::Vector3d& dv_commanded_body_mps) const {
  const PropulsionSettings& s = settings_;
  const double impulse_ns = mass_kg_ * dv_commanded_body_mps.norm();
  if (impulse_ns > s.max_impulse_ns) return core::Error{"dv_commanded_body_mps", "impulse above the maximum"};
  const double top_steps = std::floor(s.max_impulse_ns / s.quantum_ns);
  const double steps = std::min(std::round(impulse_ns / s.quantum_ns), top_steps);
  const double quantised_ns = steps * s.quantum_ns;
  if (quantised_ns < s.min_impulse_ns) {
    return core::Error{"dv_commanded_body_mps", "impulse below the minimum after quantisation"};
  }
  return quantised_ns;
}

// Step 4, direction: rotation of `unit_body` by theta ~ N(0, sigma) about the perpendicular axis
// a = cos(phi) e1 + sin(phi) e2, phi ~ U[0, 2 pi). Rodrigues' formula with a . u = 0:
// u' = u cos(theta) + (a x u) sin(theta).
Eigen::Vector3d Propulsion::perturbed_direction(const Eigen::Vector3d& unit_body) {
  const double phi = core::kTwoPi * rng_.uniform();
  const double theta = rng_.normal(settings_.direction_sigma_rad);
  const auto [e1, e2] = perpendicular_basis(unit_body);
  const Eigen::Vector3d axis = std::cos(phi) * e1 + std::sin(phi) * e2;
  return unit_body * std::cos(theta) + axis.cross(unit_body) * std::sin(theta);
}

core::Result<ExecutedImpulse> Propulsion::execute(double t_s, const Eigen::Vector3d& dv_commanded_body_mps) {
  if (!std::isfinite(t_s)) return core::Error{"t_s", "must be finite"};
  if (!dv_commanded_body_mps.allFinite()) return core::Error{"dv_commanded_body_mps", "must be finite"};
  if (last_impulse_t_ && t_s - *last_impulse_t_ < settings_.spacing_s - kSpacingTolerance_s) {
    return core::Error{"t_s", "earlier than spacing_s after the previous impulse"};
  }
  const core::Result<double> impulse = quantised_impulse_ns(dv_commanded_body_mps);
  if (!impulse) return impulse.error();
  if (!(propellant_kg_ > 0.0)) return core::Error{"dv_commanded_body_mps", "propellant exhausted"};

  Eigen::Vector3d biased_body = dv_commanded_body_mps;  // each component by the nozzle firing it
  for (int i = 0; i < 3; ++i) biased_body[i] *= 1.0 + nozzle_bias_[static_cast<std::size_t>(biased_body[i] < 0.0 ? i + 3 : i)];
  const double bias_factor = biased_body.norm() / dv_commanded_body_mps.norm();
  const double magnitude_factor = std::max(0.0, 1.0 + rng_.normal(settings_.magnitude_sigma));
  const Eigen::Vector3d direction_body =
      perturbed_direction(bias_factor > 0.0 ? Eigen::Vector3d(biased_body / biased_body.norm()) : dv_commanded_body_mps.normalized());
  double dv_mps = impulse.value() * bias_factor * magnitude_factor / mass_kg_;

  // Step 5, Tsiolkovsky: dm = m (1 - exp(-dv / (Isp g0))); expm1 keeps the tiny dm accurate.
  const double exhaust_mps = isp_s_ * kStandardGravity;
  double used_kg = -mass_kg_ * std::expm1(-dv_mps / exhaust_mps);
  if (used_kg > propellant_kg_) {  // fires what is left: dv = Isp g0 ln(m / (m - m_left))
    used_kg = propellant_kg_;
    dv_mps = -exhaust_mps * std::log1p(-used_kg / mass_kg_);
  }
  mass_kg_ -= used_kg;
  propellant_kg_ = used_kg == propellant_kg_ ? 0.0 : propellant_kg_ - used_kg;
  last_impulse_t_ = t_s;
  return ExecutedImpulse{t_s, dv_commanded_body_mps, dv_mps * direction_body, impulse.value(), used_kg, mass_kg_};
}

double thruster_l1_norm(const Eigen::Vector3d& dv_body) { return dv_body.lpNorm<1>(); }

}  // namespace visors::sim
