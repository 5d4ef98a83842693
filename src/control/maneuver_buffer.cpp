#include "control/maneuver_buffer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/QR>

#include "control/impulse_effect.hpp"

namespace visors::control {
namespace {

core::Result<bool> check_inputs(const astro::KeplerianElements& chief, const Impulse& impulse, double mass,
                                const BufferSettings& s) {
  if (!astro::validate_keplerian(chief).ok()) return core::Error{"chief", "invalid mean elements"};
  if (!std::isfinite(impulse.t)) return core::Error{"maneuver.t", "must be finite"};
  if (!impulse.dv_rtn.allFinite()) return core::Error{"maneuver.dv_rtn", "must be finite"};
  if (!(mass > 0.0) || !std::isfinite(mass)) return core::Error{"mass", "must be a finite number > 0 kg"};
  const ActuatorLimits& l = s.limits;
  if (!(l.max_impulse > 0.0) || !(l.min_impulse >= 0.0) || l.min_impulse > l.max_impulse) {
    return core::Error{"limits", "need 0 <= min_impulse <= max_impulse, max_impulse > 0"};
  }
  if (!(l.quantum >= 0.0) || l.quantum > l.max_impulse) return core::Error{"limits.quantum", "must be in [0, max_impulse]"};
  if (!(l.spacing > 0.0)) return core::Error{"limits.spacing", "must be > 0 s"};
  if (s.max_pieces < 1) return core::Error{"max_pieces", "must be >= 1"};
  if (!(s.cap_margin > 0.0 && s.cap_margin <= 1.0)) return core::Error{"cap_margin", "must be in (0, 1]"};
  return true;
}

// Piece times centred on the planned time.
std::vector<double> piece_times(double t, int pieces, double spacing) {
  std::vector<double> times(static_cast<std::size_t>(pieces));
  for (int j = 0; j < pieces; ++j) times[static_cast<std::size_t>(j)] = t + (j - 0.5 * (pieces - 1)) * spacing;
  return times;
}

// Columns of the effect matrices of `times` at t_ref, side by side (6 x 3K).
Eigen::MatrixXd stacked_effects(const astro::KeplerianElements& chief, const std::vector<double>& times,
                                double t_ref, const core::EarthGravityConstants& gravity) {
  Eigen::MatrixXd b(6, 3 * static_cast<Eigen::Index>(times.size()));
  for (std::size_t j = 0; j < times.size(); ++j) {
    b.middleCols<3>(3 * static_cast<Eigen::Index>(j)) = impulse_effect(chief, times[j], t_ref, gravity);
  }
  return b;
}

}  // namespace

namespace {

// The split with what the quantisation needs: the pieces' effect matrices side by side (6 x 3K)
// and the planned impulse's effect, both at the last piece's time.
struct Split {
  std::vector<Impulse> pieces;
  Eigen::MatrixXd effects;
  astro::RelativeOrbitalElements target;
};

core::Result<Split> split(const astro::KeplerianElements& chief_mean_t0, const Impulse& impulse, double mass,
                          const BufferSettings& settings) {
  if (auto ok = check_inputs(chief_mean_t0, impulse, mass, settings); !ok) return ok.error();
  const double cap = settings.cap_margin * settings.limits.max_impulse / mass;  // [m/s]
  const double dv = impulse.dv_rtn.norm();
  if (dv <= cap) {
    const Eigen::Matrix<double, 6, 3> effect = impulse_effect(chief_mean_t0, impulse.t, impulse.t, settings.gravity);
    return Split{{impulse}, effect, effect * impulse.dv_rtn};
  }
  for (int pieces = std::max(2, static_cast<int>(std::ceil(dv / cap))); pieces <= settings.max_pieces; ++pieces) {
    const std::vector<double> times = piece_times(impulse.t, pieces, settings.limits.spacing);
    const double t_ref = times.back();
    Split out{std::vector<Impulse>(times.size()), stacked_effects(chief_mean_t0, times, t_ref, settings.gravity),
              impulse_effect(chief_mean_t0, impulse.t, t_ref, settings.gravity) * impulse.dv_rtn};
    // Minimum-norm solution of effects x = target (full row rank for >= 2 distinct times).
    const Eigen::VectorXd x = out.effects.completeOrthogonalDecomposition().solve(out.target);
    bool within_cap = true;
    for (std::size_t j = 0; j < times.size(); ++j) {
      out.pieces[j] = {times[j], x.segment<3>(3 * static_cast<Eigen::Index>(j))};
      within_cap = within_cap && out.pieces[j].dv_rtn.norm() <= cap;
    }
    if (within_cap) return out;
  }
  return core::Error{"maneuver.dv_rtn", "needs more than max_pieces = " + std::to_string(settings.max_pieces) +
                                            " pieces of at most " + std::to_string(settings.limits.max_impulse) +
                                            " N s"};
}

}  // namespace

core::Result<std::vector<Impulse>> split_impulse(const astro::KeplerianElements& chief_mean_t0, const Impulse& impulse,
                                                 double mass, const BufferSettings& settings) {
  auto result = split(chief_mean_t0, impulse, mass, settings);
  if (!result) return result.error();
  return std::move(result).value().pieces;
}

core::Result<BufferedManeuver> buffer_impulse(const astro::KeplerianElements& chief_mean_t0, const Impulse& impulse,
                                              double mass, const BufferSettings& settings) {
  auto result = split(chief_mean_t0, impulse, mass, settings);
  if (!result) return result.error();
  Split parts = std::move(result).value();
  std::vector<Impulse>& pieces = parts.pieces;
  const Eigen::MatrixXd& b = parts.effects;
  const ActuatorLimits& limits = settings.limits;

  // Quantise piece j, then give what its rounding left to the pieces after it.
  astro::RelativeOrbitalElements remaining = parts.target;
  const auto n = static_cast<Eigen::Index>(pieces.size());
  for (Eigen::Index j = 0; j < n; ++j) {
    Impulse& piece = pieces[static_cast<std::size_t>(j)];
    const double impulse_ns = mass * piece.dv_rtn.norm();
    double quantised = limits.quantum > 0.0 ? std::round(impulse_ns / limits.quantum) * limits.quantum : impulse_ns;
    if (quantised > limits.max_impulse) quantised -= limits.quantum;
    if (quantised < limits.min_impulse) quantised = 0.0;
    piece.dv_rtn = impulse_ns > 0.0 ? Eigen::Vector3d(piece.dv_rtn * (quantised / impulse_ns)) : Eigen::Vector3d::Zero();
    remaining -= b.middleCols<3>(3 * j) * piece.dv_rtn;
    if (j + 1 < n) {
      const Eigen::MatrixXd rest = b.rightCols(3 * (n - j - 1));
      const Eigen::VectorXd x = rest.completeOrthogonalDecomposition().solve(remaining);
      for (Eigen::Index k = j + 1; k < n; ++k) pieces[static_cast<std::size_t>(k)].dv_rtn = x.segment<3>(3 * (k - j - 1));
    }
  }
  BufferedManeuver out;
  for (const Impulse& p : pieces) {
    if (p.dv_rtn.squaredNorm() > 0.0) out.pieces.push_back(p);
  }
  out.residual_roe_m = chief_mean_t0.a * remaining;
  out.dv_total = total_delta_v(out.pieces);
  return out;
}

}  // namespace visors::control
