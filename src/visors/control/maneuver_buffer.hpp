#pragma once
// Maneuver buffering: one planned impulse -> a sequence of actuator-feasible pieces with the same
// net first-order effect on the mean ROE.
//
// Actuator (Guffanti et al., AAS 23-149, 2023, Table 1(b), propulsion system performance):
// impulse 1e-3 .. 2.2e-2 N s, quantised in steps of 6e-5 N s, one impulse every 46.5 s.
//
// Method: K pieces centred on the planned time (offsets (j - (K-1)/2) * 46.5 s: centring keeps
// the dlambda and rotation errors of a one-sided schedule away), their velocity changes the
// minimum-norm solution of
//     sum_j Phi(t_K, t_j) Gamma(t_j) dv_j = Phi(t_K, t) Gamma(t) dv        (6 equations, 3K unknowns)
// with the J2 STM and the eccentric control input matrix at each piece's chief (so the net effect
// is exact in the planners' linear model, J2 and eccentricity included), and K increased until
// every piece is below the maximum impulse. Then the pieces are quantised one after the other
// (magnitude rounded to the impulse quantum, pieces below the minimum impulse dropped), each time
// re-solving the remaining pieces for what the rounding left, so only the last piece's rounding
// (<= half a quantum) remains.
//
// This replaces the paper's Algorithm 5 (same reference, sec. 4.3, maneuver buffering), which
// (i) scales the radial pieces by 1/c (c the Dirichlet factor), which changes their sum and so
// dlambda by -2/n dv_R (1/c - 1); (ii) computes the compensating radial pieces from
// dv_T - dv_Ti (1 + 2N), which is identically zero, so the tangential part of the de effect is
// left short by the factor c (5-18 % for 60-120 deg spans); (iii) caps the 1-norm of the pieces
// before the compensation is added (docs/algorithms/control.md#maneuver-buffering). The
// minimum-norm solve has none of these problems and covers the eccentric, J2 case the paper's
// closed forms do not.

#include <memory>
#include <vector>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/control/impulse.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/status.hpp"

namespace visors::control {

/// The propulsion system's limits (Guffanti et al., AAS 23-149, 2023, Table 1(b)).
struct ActuatorLimits {
  double max_impulse_ns = 2.2e-2;  // [N s]
  double min_impulse_ns = 1.0e-3;  // [N s]
  double quantum_ns = 6.0e-5;      // impulse quantisation [N s]
  double spacing_s = 46.5;        // time between impulses [s]
};

struct BufferSettings {
  ActuatorLimits limits;
  int max_pieces = 99;             // upper bound on K [-]
  double cap_margin = 0.98;        // pieces are sized to this fraction of max_impulse before quantisation [-]
  core::EarthGravityConstants gravity;
};

struct BufferedManeuver {
  std::vector<Impulse> pieces;  // sorted by time; every one executable as is
  /// Net-effect error of the pieces against the planned impulse, Phi(t_K, .) frame, a*dROE [m]
  /// (from the quantisation of the last piece and dropped sub-minimum pieces).
  Eigen::Matrix<double, 6, 1> residual_roe_m = Eigen::Matrix<double, 6, 1>::Zero();
  double dv_total_mps = 0.0;  // sum of the pieces' |dv| [m/s]
};

/// The buffer with its storage sized once (at most kMaxBufferPieces pieces; fixed-capacity
/// matrices and decompositions, reserved piece vectors), so buffering an impulse allocates
/// nothing: the flight component's form. buffer_impulse and split_impulse below wrap it.
inline constexpr int kMaxBufferPieces = 99;

class ImpulseBuffer {
 public:
  ImpulseBuffer();
  ImpulseBuffer(ImpulseBuffer&&) noexcept;
  ImpulseBuffer& operator=(ImpulseBuffer&&) noexcept;
  ~ImpulseBuffer();

  /// The unquantised split into pieces() (as split_impulse). Errors as buffer_impulse, and
  /// "max_pieces" above kMaxBufferPieces.
  core::Status split(const astro::KeplerianElements& chief_mean_t0, const Impulse& impulse, double mass,
                           const BufferSettings& settings);
  /// The split, quantised, into result() (as buffer_impulse).
  core::Status buffer(const astro::KeplerianElements& chief_mean_t0, const Impulse& impulse, double mass,
                            const BufferSettings& settings);

  [[nodiscard]] const std::vector<Impulse>& pieces() const { return pieces_; }
  [[nodiscard]] const BufferedManeuver& result() const { return result_; }

 private:
  struct Work;  // the fixed-capacity matrices (kept out of the header)
  std::vector<Impulse> pieces_;
  BufferedManeuver result_;
  std::unique_ptr<Work> work_;  // one allocation at construction (~50 kB of matrices)
};

/// Splits `impulse` (t since the epoch of `chief_mean_t0`, the chief's mean elements at t = 0)
/// for a spacecraft of `mass` [kg]. Before quantisation the net effect is exact to round-off.
/// Errors: non-finite input, mass <= 0, an impulse that needs more than max_pieces pieces.
core::Result<BufferedManeuver> buffer_impulse(const astro::KeplerianElements& chief_mean_t0, const Impulse& impulse,
                                              double mass, const BufferSettings& settings = {});

/// The unquantised split (the first stage of buffer_impulse): pieces within the maximum impulse,
/// same net effect in the linear model.
core::Result<std::vector<Impulse>> split_impulse(const astro::KeplerianElements& chief_mean_t0,
                                                 const Impulse& impulse, double mass,
                                                 const BufferSettings& settings = {});

}  // namespace visors::control
