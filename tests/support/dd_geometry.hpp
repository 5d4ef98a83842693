#pragma once
// Float ambiguity problems from a realistic double-difference (DD) geometry, shared by the nav
// tests and benchmarks (the first benchmark family of bench/bench_ambiguity.cpp, docs/results.md
// "Performance": single-epoch L1/L2 short-baseline DD geometry):
// - `satellites` satellites, azimuth uniform in [0, 2 pi), sin(elevation) uniform in
//   [sin 10 deg, 1]; the highest is the reference;
// - one epoch, short baseline: unknowns the 3D baseline and the DD ambiguities of each frequency
//   (L1, or L1 and L2), n = (satellites - 1) x frequencies;
// - DD phase and code with undifferenced sigmas phase_sigma_m and code_sigma_m and the DD
//   cofactor 2 (I + 1 1') of a common reference (independent per frequency and type);
// - Q = the ambiguity block of (A' W A)^-1 [cycles^2].
// Float ambiguities for a simulation: integers uniform in +-1e6 plus a draw of N(0, Q).

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <random>

namespace visors::test {

struct DdGeometryOptions {
  int satellites = 13;
  int frequencies = 2;          // 1: L1 only, 2: L1 and L2
  double phase_sigma_m = 0.003;  // undifferenced carrier phase
  double code_sigma_m = 0.3;     // undifferenced code
};

inline constexpr double kL1WavelengthM = 299792458.0 / 1575.42e6;  // IS-GPS-200 carrier frequencies
inline constexpr double kL2WavelengthM = 299792458.0 / 1227.60e6;

/// Unit lines of sight (rows, local east-north-up) of `satellites` satellites drawn as above, and
/// the index of the highest (the reference).
struct LinesOfSight {
  Eigen::MatrixXd los;
  int reference = 0;
};

inline LinesOfSight draw_lines_of_sight(int satellites, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit;
  LinesOfSight out{Eigen::MatrixXd(satellites, 3), 0};
  double highest = -1.0;
  for (int i = 0; i < satellites; ++i) {
    const double azimuth = 2.0 * std::numbers::pi * unit(rng);
    const double sin_el = std::sin(10.0 * std::numbers::pi / 180.0) + (1.0 - std::sin(10.0 * std::numbers::pi / 180.0)) * unit(rng);
    const double cos_el = std::sqrt(1.0 - sin_el * sin_el);
    out.los.row(i) << cos_el * std::sin(azimuth), cos_el * std::cos(azimuth), sin_el;
    if (sin_el > highest) {
      highest = sin_el;
      out.reference = i;
    }
  }
  return out;
}

/// Q of the DD ambiguities [cycles^2], n = (satellites - 1) x frequencies.
inline Eigen::MatrixXd dd_ambiguity_covariance(const DdGeometryOptions& o, std::mt19937_64& rng) {
  const int s = o.satellites;
  const LinesOfSight sight = draw_lines_of_sight(s, rng);
  const Eigen::MatrixXd& los = sight.los;
  const int reference = sight.reference;
  const int dd = s - 1;
  Eigen::MatrixXd u(dd, 3);
  for (int i = 0, r = 0; i < s; ++i) {
    if (i != reference) u.row(r++) = los.row(i) - los.row(reference);
  }
  const int f = o.frequencies;
  const int n = dd * f;
  const double wavelengths[2] = {kL1WavelengthM, kL2WavelengthM};
  const Eigen::MatrixXd cofactor_inv =
      (2.0 * (Eigen::MatrixXd::Identity(dd, dd) + Eigen::MatrixXd::Ones(dd, dd))).inverse();
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(3 + n, 3 + n);
  for (int k = 0; k < f; ++k) {
    Eigen::MatrixXd phase = Eigen::MatrixXd::Zero(dd, 3 + n);
    phase.leftCols(3) = u;
    phase.block(0, 3 + k * dd, dd, dd).diagonal().setConstant(wavelengths[k]);
    Eigen::MatrixXd code = Eigen::MatrixXd::Zero(dd, 3 + n);
    code.leftCols(3) = u;
    normal += phase.transpose() * cofactor_inv * phase / (o.phase_sigma_m * o.phase_sigma_m);
    normal += code.transpose() * cofactor_inv * code / (o.code_sigma_m * o.code_sigma_m);
  }
  const Eigen::MatrixXd covariance = normal.inverse();
  Eigen::MatrixXd q = covariance.bottomRightCorner(n, n);
  return 0.5 * (q + q.transpose());
}

/// Covariance of a single-difference (SD) filter state [baseline (3) m, SD ambiguities [cycles] of
/// each frequency, satellites in the order of `sight`] after one epoch of SD phase and code
/// (undifferenced sigmas of `o` times sqrt 2, independent; SD ranges u_i' b) with the SD receiver
/// clock [m] estimated and eliminated, and a prior of baseline_prior_sigma_m per axis on the
/// baseline (what a running filter carries over from its dynamics). The SD ambiguities' common
/// part is fixed by the code alone; their differences (the DDs) by phase and the baseline.
inline Eigen::MatrixXd sd_filter_covariance(const LinesOfSight& sight, const DdGeometryOptions& o,
                                            double baseline_prior_sigma_m) {
  const auto s = sight.los.rows();
  const int f = o.frequencies;
  const auto n = 3 + s * f + 1;  // baseline, SD ambiguities, clock (last)
  const double wavelengths[2] = {kL1WavelengthM, kL2WavelengthM};
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(n, n);
  normal.topLeftCorner(3, 3).diagonal().setConstant(1.0 / (baseline_prior_sigma_m * baseline_prior_sigma_m));
  for (int k = 0; k < f; ++k) {
    Eigen::MatrixXd phase = Eigen::MatrixXd::Zero(s, n);
    phase.leftCols(3) = sight.los;
    phase.block(0, 3 + k * s, s, s).diagonal().setConstant(wavelengths[k]);
    phase.col(n - 1).setOnes();
    Eigen::MatrixXd code = Eigen::MatrixXd::Zero(s, n);
    code.leftCols(3) = sight.los;
    code.col(n - 1).setOnes();
    normal += phase.transpose() * phase / (2.0 * o.phase_sigma_m * o.phase_sigma_m);
    normal += code.transpose() * code / (2.0 * o.code_sigma_m * o.code_sigma_m);
  }
  const Eigen::MatrixXd covariance = normal.inverse();
  Eigen::MatrixXd p = covariance.topLeftCorner(n - 1, n - 1);
  return 0.5 * (p + p.transpose());
}

/// Integer ambiguities uniform in +-range.
inline Eigen::VectorXd random_integers(Eigen::Index n, double range, std::mt19937_64& rng) {
  std::uniform_int_distribution<long> draw(-static_cast<long>(range), static_cast<long>(range));
  Eigen::VectorXd z(n);
  for (Eigen::Index i = 0; i < n; ++i) z(i) = static_cast<double>(draw(rng));
  return z;
}

/// z + e, e ~ N(0, Q), with chol_lower the lower Cholesky factor of Q.
inline Eigen::VectorXd float_ambiguities(const Eigen::VectorXd& z, const Eigen::MatrixXd& chol_lower, std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  Eigen::VectorXd e(z.size());
  for (Eigen::Index i = 0; i < z.size(); ++i) e(i) = gauss(rng);
  return z + chol_lower * e;
}

}  // namespace visors::test
