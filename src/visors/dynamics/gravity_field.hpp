#pragma once
// Spherical-harmonic Earth gravity field: the fully normalised coefficients C̄_nm, S̄_nm of one
// model with its own GM and reference radius, read from an ICGEM `.gfc` file on the ground
// (dynamics/files/icgem_file.hpp), or the embedded low-degree default. Evaluation lives in
// spherical_harmonic_gravity.hpp.
//
// Convention (docs/algorithms/dynamics.md#potential-and-normalisation): geodesy normalisation
//   P̄_nm = sqrt((2 - δ_0m)(2n + 1)(n - m)!/(n + m)!) P_nm, no Condon-Shortley phase,
//   U = (GM/r) Σ_n Σ_m (R/r)^n P̄_nm(sin φ) [C̄_nm cos mλ + S̄_nm sin mλ].

#include <cstddef>
#include <string>
#include <vector>

namespace visors::dynamics {

/// ICGEM `tide_system` header value. C̄20 differs by ~4.2e-9 between zero-tide and tide-free
/// (IERS Conventions 2010 §6.2.2); the field is used as read, no conversion is made.
enum class TideSystem { kUnknown, kZeroTide, kTideFree, kMeanTide };

/// Fully normalised coefficients of one gravity model, complete to `max_degree` (all orders).
/// Invariant: c_bar.size() == s_bar.size() == coefficient_count(max_degree); S̄_n0 == 0.
struct GravityField {
  std::string model_name;
  double gm = 0.0;       // [m^3/s^2], the model's own value (must be used with these C̄/S̄)
  double radius = 0.0;   // [m], the model's reference radius R
  int max_degree = -1;   // N: the coefficients hold degrees 0..N
  TideSystem tide_system = TideSystem::kUnknown;
  std::vector<double> c_bar;  // [-], C̄_nm at index(n, m)
  std::vector<double> s_bar;  // [-], S̄_nm at index(n, m)

  /// Flat triangular layout, row by degree: (n, m) -> n(n+1)/2 + m, 0 <= m <= n.
  [[nodiscard]] static constexpr std::size_t index(int n, int m) {
    return static_cast<std::size_t>(n) * static_cast<std::size_t>(n + 1) / 2 +
           static_cast<std::size_t>(m);
  }
  /// Number of (n, m) pairs for degrees 0..n_max: (n_max+1)(n_max+2)/2.
  [[nodiscard]] static constexpr std::size_t coefficient_count(int n_max) {
    return n_max < 0 ? 0 : index(n_max + 1, 0);
  }
  /// C̄_nm; precondition 0 <= m <= n <= max_degree.
  [[nodiscard]] double c(int n, int m) const { return c_bar[index(n, m)]; }
  /// S̄_nm; precondition 0 <= m <= n <= max_degree.
  [[nodiscard]] double s(int n, int m) const { return s_bar[index(n, m)]; }
};

/// "zero_tide", "tide_free", "mean_tide" or "unknown".
const char* to_string(TideSystem tide_system);

/// Embedded default field: GGM05S (Tapley et al. 2013, ICGEM), fully normalised, complete to
/// degree and order 8, zero-tide, GM = 3.986004415e14 m^3/s^2, R = 6378136.3 m. For use when no
/// gravity file is available (e.g. on-board without uplink, or a CI machine without data).
GravityField embedded_gravity_field();

}  // namespace visors::dynamics
