#include "visors/control/maneuver_buffer.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/QR>

#include "visors/control/impulse_effect.hpp"

namespace visors::control {
namespace {

core::Status check_inputs(const astro::KeplerianElements& chief, const Impulse& impulse, double mass,
                                const BufferSettings& s) {
  if (!astro::validate_keplerian(chief).ok()) return core::Status{core::Problem::kOutOfRange, "chief", "invalid mean elements"};
  if (!std::isfinite(impulse.t)) return core::Status{core::Problem::kNotFinite, "maneuver.t", "must be finite"};
  if (!impulse.dv_rtn.allFinite()) return core::Status{core::Problem::kNotFinite, "maneuver.dv_rtn", "must be finite"};
  if (!(mass > 0.0) || !std::isfinite(mass)) return core::Status{core::Problem::kOutOfRange, "mass", "must be a finite number > 0 kg"};
  const ActuatorLimits& l = s.limits;
  if (!(l.max_impulse_ns > 0.0) || !(l.min_impulse_ns >= 0.0) || l.min_impulse_ns > l.max_impulse_ns) {
    return core::Status{core::Problem::kOutOfRange, "limits", "need 0 <= min_impulse <= max_impulse, max_impulse > 0"};
  }
  if (!(l.quantum_ns >= 0.0) || l.quantum_ns > l.max_impulse_ns) return core::Status{core::Problem::kOutOfRange, "limits.quantum_ns", "must be in [0, max_impulse]"};
  if (!(l.spacing_s > 0.0)) return core::Status{core::Problem::kOutOfRange, "limits.spacing_s", "must be > 0 s"};
  if (s.max_pieces < 1) return core::Status{core::Problem::kOutOfRange, "max_pieces", "must be >= 1"};
  if (!(s.cap_margin > 0.0 && s.cap_margin <= 1.0)) return core::Status{core::Problem::kOutOfRange, "cap_margin", "must be in (0, 1]"};
  return {};
}

using Effects = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 3 * kMaxBufferPieces>;
using PieceVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3 * kMaxBufferPieces, 1>;

}  // namespace

// The pieces' effect matrices side by side (6 x 3K) at the last piece's time, the planned
// impulse's effect there, and the minimum-norm solver; all fixed capacity, so nothing allocates.
struct ImpulseBuffer::Work {
  Effects effects;
  astro::RelativeOrbitalElements target = astro::RelativeOrbitalElements::Zero();
  Eigen::CompleteOrthogonalDecomposition<Effects> cod;
  PieceVector x;
  PieceVector householder_workspace;
  Effects rest;

  // x = the minimum-norm solution of (the matrix cod was computed on) x = rhs. With E P = Q [T 0] Z
  // (complete orthogonal decomposition), x = P Z' [T^-1 Q' rhs; 0]. Written out here because
  // Eigen's solve() applies Z' with a heap-allocated temporary; this uses the fixed-capacity
  // workspace, with the same operations in the same order (so the same bits).
  void solve_min_norm(const Eigen::Matrix<double, 6, 1>& rhs) {
    const Eigen::Index rank = cod.rank();
    const Eigen::Index cols = cod.cols();
    x.resize(cols);
    if (rank == 0) {
      x.setZero();
      return;
    }
    Eigen::Matrix<double, 6, 1> c = rhs;
    c.applyOnTheLeft(cod.matrixQ().setLength(rank).adjoint());
    x.topRows(rank) = cod.matrixT().topLeftCorner(rank, rank).template triangularView<Eigen::Upper>().solve(c.topRows(rank));
    if (rank < cols) {
      x.bottomRows(cols - rank).setZero();
      householder_workspace.resize(std::max<Eigen::Index>(cols, 1));
      for (Eigen::Index k = 0; k < rank; ++k) {
        if (k != rank - 1) x.row(k).swap(x.row(rank - 1));
        x.middleRows(rank - 1, cols - rank + 1)
            .applyHouseholderOnTheLeft(cod.matrixQTZ().row(k).tail(cols - rank).adjoint(), cod.zCoeffs()(k),
                                       householder_workspace.data());
        if (k != rank - 1) x.row(k).swap(x.row(rank - 1));
      }
    }
    x = cod.colsPermutation() * x;
  }
};

ImpulseBuffer::ImpulseBuffer() : work_(std::make_unique<Work>()) {
  pieces_.reserve(kMaxBufferPieces);
  result_.pieces.reserve(kMaxBufferPieces);
}
ImpulseBuffer::ImpulseBuffer(ImpulseBuffer&&) noexcept = default;
ImpulseBuffer& ImpulseBuffer::operator=(ImpulseBuffer&&) noexcept = default;
ImpulseBuffer::~ImpulseBuffer() = default;

core::Status ImpulseBuffer::split(const astro::KeplerianElements& chief_mean_t0, const Impulse& impulse,
                                        double mass, const BufferSettings& settings) {
  if (auto ok = check_inputs(chief_mean_t0, impulse, mass, settings); !ok) return ok;
  if (settings.max_pieces > kMaxBufferPieces) return core::Status{core::Problem::kOutOfRange, "max_pieces", "must be <= 99"};
  Work& w = *work_;
  pieces_.clear();
  const double cap = settings.cap_margin * settings.limits.max_impulse_ns / mass;  // [m/s]
  const double dv = impulse.dv_rtn.norm();
  if (dv <= cap) {
    w.effects.resize(6, 3);
    w.effects = impulse_effect(chief_mean_t0, impulse.t, impulse.t, settings.gravity);
    w.target = w.effects * impulse.dv_rtn;
    pieces_.push_back(impulse);
    return {};
  }
  for (int count = std::max(2, static_cast<int>(std::ceil(dv / cap))); count <= settings.max_pieces; ++count) {
    // Piece times centred on the planned time.
    const auto time = [&](int j) { return impulse.t + (j - 0.5 * (count - 1)) * settings.limits.spacing_s; };
    const double t_ref = time(count - 1);
    w.effects.resize(6, 3 * count);
    for (int j = 0; j < count; ++j) w.effects.middleCols<3>(3 * j) = impulse_effect(chief_mean_t0, time(j), t_ref, settings.gravity);
    w.target = impulse_effect(chief_mean_t0, impulse.t, t_ref, settings.gravity) * impulse.dv_rtn;
    // Minimum-norm solution of effects x = target (full row rank for >= 2 distinct times).
    w.cod.compute(w.effects);
    w.solve_min_norm(w.target);
    pieces_.clear();
    bool within_cap = true;
    for (int j = 0; j < count; ++j) {
      pieces_.push_back({time(j), w.x.segment<3>(3 * j)});
      within_cap = within_cap && pieces_.back().dv_rtn.norm() <= cap;
    }
    if (within_cap) return {};
  }
  return core::Status{core::Problem::kCapacity, "maneuver.dv_rtn", "needs more than max_pieces pieces of at most max_impulse_ns"};
}

core::Status ImpulseBuffer::buffer(const astro::KeplerianElements& chief_mean_t0, const Impulse& impulse,
                                         double mass, const BufferSettings& settings) {
  if (auto ok = split(chief_mean_t0, impulse, mass, settings); !ok) return ok;
  Work& w = *work_;
  const ActuatorLimits& limits = settings.limits;
  // Quantise piece j, then give what its rounding left to the pieces after it.
  astro::RelativeOrbitalElements remaining = w.target;
  const auto n = static_cast<Eigen::Index>(pieces_.size());
  for (Eigen::Index j = 0; j < n; ++j) {
    Impulse& piece = pieces_[static_cast<std::size_t>(j)];
    const double impulse_ns = mass * piece.dv_rtn.norm();
    double quantised = limits.quantum_ns > 0.0 ? std::round(impulse_ns / limits.quantum_ns) * limits.quantum_ns : impulse_ns;
    if (quantised > limits.max_impulse_ns) quantised -= limits.quantum_ns;
    if (quantised < limits.min_impulse_ns) quantised = 0.0;
    piece.dv_rtn = impulse_ns > 0.0 ? Eigen::Vector3d(piece.dv_rtn * (quantised / impulse_ns)) : Eigen::Vector3d::Zero();
    remaining -= w.effects.middleCols<3>(3 * j) * piece.dv_rtn;
    if (j + 1 < n) {
      w.rest = w.effects.rightCols(3 * (n - j - 1));
      w.cod.compute(w.rest);
      w.solve_min_norm(remaining);
      for (Eigen::Index k = j + 1; k < n; ++k) pieces_[static_cast<std::size_t>(k)].dv_rtn = w.x.segment<3>(3 * (k - j - 1));
    }
  }
  result_.pieces.clear();
  for (const Impulse& p : pieces_) {
    if (p.dv_rtn.squaredNorm() > 0.0) result_.pieces.push_back(p);
  }
  result_.residual_roe_m = chief_mean_t0.a * remaining;
  result_.dv_total_mps = total_delta_v(result_.pieces);
  return {};
}

core::Result<std::vector<Impulse>> split_impulse(const astro::KeplerianElements& chief_mean_t0, const Impulse& impulse,
                                                 double mass, const BufferSettings& settings) {
  ImpulseBuffer buffer;
  if (auto ok = buffer.split(chief_mean_t0, impulse, mass, settings); !ok) return ok.error();
  return buffer.pieces();
}

core::Result<BufferedManeuver> buffer_impulse(const astro::KeplerianElements& chief_mean_t0, const Impulse& impulse,
                                              double mass, const BufferSettings& settings) {
  ImpulseBuffer buffer;
  if (auto ok = buffer.buffer(chief_mean_t0, impulse, mass, settings); !ok) return ok.error();
  return buffer.result();
}

}  // namespace visors::control
