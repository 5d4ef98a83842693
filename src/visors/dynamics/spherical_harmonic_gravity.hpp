#pragma once
// Spherical-harmonic gravity: acceleration, potential and gravity gradient of a GravityField in
// the body-fixed frame (ITRF), truncated to degree N and order M.
//
// Algorithm: the fully normalised Cunningham V/W recursion (Cunningham 1970, "On the computation
// of the spherical harmonic terms needed during the numerical integration of the orbital motion
// of an artificial satellite", Celest. Mech. 2; Montenbruck & Gill 2000, "Satellite Orbits"
// §3.2.5, eqs. 3.29-3.33), here fully normalised: M&G's factors times ratios of the normalisation
// factors, with δ = 2 at m = 1 (docs/algorithms/dynamics.md#normalised-cunningham-recursion).
// V̄_nm + iW̄_nm = (R/r)^(n+1) P̄_nm(sin φ) e^(imλ) are built by recursion in Cartesian
// coordinates, so there is no singularity at the poles.
//
// Cost: every square root is computed once in create(); the derivative relations are folded into
// the model's coefficients there (the acceleration is a linear form in V̄/W̄ of degree <= N+1), so
// one evaluation is the V/W recursion plus 6 (8 with the potential) multiply-adds per (n, m),
// over flat arrays, and allocates nothing.
//
// Threading: an instance owns its evaluation workspace, so the evaluation functions are not
// const and one instance must not be evaluated from two threads at once (copy it instead; a copy
// has its own workspace).

#include <vector>

#include <Eigen/Core>

#include "visors/core/result.hpp"
#include "visors/dynamics/gravity_field.hpp"

namespace visors::dynamics {

/// Acceleration and potential of one evaluation.
struct GravityAccelerationPotential {
  Eigen::Vector3d a_itrf;  // [m/s^2], body-fixed
  double potential;        // [m^2/s^2], U = GM/r + ... (positive convention, a = grad U)
};

class SphericalHarmonicGravity {
 public:
  /// Highest degree accepted. The recursion itself is stable far beyond (normalised V/W); the
  /// limit only bounds the memory (~0.8 MB of coefficients at 360) and keeps (R/r)^(n+2) away
  /// from underflow at 40,000 km.
  static constexpr int kMaxDegree = 360;

  /// Validates 0 <= degree <= min(field.max_degree, kMaxDegree), 0 <= order <= degree, a
  /// consistent field (gm > 0, radius > 0, coefficient arrays sized for its max_degree), and
  /// precomputes everything an evaluation needs.
  static core::Result<SphericalHarmonicGravity> create(const GravityField& field, int degree, int order);

  /// Gravitational acceleration a = grad U at r_itrf [m], body-fixed [m/s^2] (central term
  /// included). Precondition: |r_itrf| > 0 (the caller rejects positions inside the Earth; the
  /// series diverges below the Brillouin sphere anyway).
  Eigen::Vector3d acceleration(const Eigen::Vector3d& r_itrf);

  /// Potential U = (GM/r) Σ (R/r)^n P̄_nm (C̄ cos mλ + S̄ sin mλ) [m^2/s^2]. Precondition |r| > 0.
  double potential(const Eigen::Vector3d& r_itrf);

  /// Acceleration and potential in one pass (measured ~25 % dearer than the acceleration alone).
  GravityAccelerationPotential acceleration_and_potential(const Eigen::Vector3d& r_itrf);

  /// Gravity gradient ∂a/∂r [1/s^2] (body-fixed, full field incl. the central term), analytic:
  /// the V/W derivative relations applied twice, so the recursion runs to degree N+2. All nine
  /// entries are computed independently, so symmetry and trace = 0 (Laplace) are checks, not
  /// assumptions. Precondition |r| > 0.
  Eigen::Matrix3d gradient(const Eigen::Vector3d& r_itrf);

  [[nodiscard]] int degree() const { return degree_; }
  [[nodiscard]] int order() const { return order_; }
  [[nodiscard]] double gm() const { return gm_; }          // [m^3/s^2]
  [[nodiscard]] double radius() const { return radius_; }  // [m]

 private:
  SphericalHarmonicGravity() = default;

  // The steps of create(), in order (allocation happens only there).
  using UnpackedArrays = std::vector<std::vector<double>>;  // the kRowArrays arrays, each over all (j, k)
  [[nodiscard]] int row_count() const { return degree_ + 3; }  // rows 0..N+2
  std::size_t lay_out_rows();
  void compute_recursion_factors(UnpackedArrays& arrays);
  void compute_derivative_factors();
  void fold_derivatives_into_coefficients(const GravityField& field, UnpackedArrays& arrays);
  void pack_rows(const UnpackedArrays& arrays, std::size_t total);

  // Runs the V/W recursion over rows 0..N (+1 with the acceleration) and accumulates the linear
  // forms selected by the template flags.
  template <bool kWithAcceleration, bool kWithPotential>
  void evaluate(const Eigen::Vector3d& r_itrf, Eigen::Vector3d* a_itrf, double* potential);

  // Per-row arrays of the packed coefficient block (see packed_).
  enum RowArray : int { kRecA, kRecB, kAxV, kAxW, kAyV, kAyW, kAzV, kAzW, kUV, kUW, kRowArrays };
  [[nodiscard]] std::size_t offset(int j) const { return row_offset_[static_cast<std::size_t>(j)]; }
  [[nodiscard]] int row_length(int j) const { return row_length_[static_cast<std::size_t>(j)]; }
  [[nodiscard]] const double* row_array(int j, RowArray q) const {
    return packed_.data() + kRowArrays * offset(j) + static_cast<std::size_t>(q * row_length(j));
  }

  double gm_ = 0.0;      // [m^3/s^2]
  double radius_ = 0.0;  // [m]
  int degree_ = 0;       // N
  int order_ = 0;        // M

  // Layout: rows j = 0..N+2, row j holds orders k = 0..min(j, M+2) (row_length_[j] entries) at
  // row_offset_[j] in the per-(j, k) arrays.
  std::vector<std::size_t> row_offset_;
  std::vector<int> row_length_;
  std::size_t row_stride_ = 0;  // workspace row length, M+3

  // Packed per row j (one contiguous stream for the evaluation loop): kRowArrays arrays of
  // row_length(j) values each:
  //  - kRecA, kRecB: general recursion term a_jk, b_jk (k <= j-2; docs/algorithms/dynamics.md);
  //  - kAxV..kAzW: the acceleration as linear forms in V̄_jk, W̄_jk (j <= N+1):
  //    a_x/(GM/R^2) = Σ_jk (AxV V̄_jk + AxW W̄_jk), likewise y and z;
  //  - kUV, kUW: the potential U/(GM/R) = Σ (C̄ V̄ + S̄ W̄) (j <= N).
  std::vector<double> packed_;
  // Sectorial factor c_j and sub-diagonal factor sqrt(2j+1), per row.
  std::vector<double> sectorial_, subdiagonal_;

  // Derivative factors of V̄_jk (j <= N+1) for the gradient: f1, f2, f3 at (j, k)
  // (docs/algorithms/dynamics.md#normalised-cunningham-recursion);
  // at k = 0, f1 holds g = sqrt(k_j (j+1)(j+2)/2). Same offsets as the packed arrays.
  std::vector<double> f1_, f2_, f3_;

  // Workspace: three rolling rows of V̄/W̄ and per-order partial sums (no allocation per call).
  std::vector<double> v_rows_, w_rows_;
  std::vector<double> sums_;  // 9 blocks of row_stride_
};

}  // namespace visors::dynamics
