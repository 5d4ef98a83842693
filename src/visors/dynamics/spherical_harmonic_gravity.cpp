#include "visors/dynamics/spherical_harmonic_gravity.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace visors::dynamics {
namespace {

// Derivative factors of the normalised V/W functions: the un-normalised M&G eq. 3.33 factors times
// the ratios N_nm/N_{n+1,k} (docs/algorithms/dynamics.md#normalised-cunningham-recursion).
// With D = R·∂/∂x etc.:
//   D_x V̄_n0 = -g V̄_{n+1,1},                 D_y V̄_n0 = -g W̄_{n+1,1}
//   D_x V̄_nm = -f1 V̄_{n+1,m+1} + f2 V̄_{n+1,m-1},   D_x W̄_nm = -f1 W̄_{n+1,m+1} + f2 W̄_{n+1,m-1}
//   D_y V̄_nm = -f1 W̄_{n+1,m+1} - f2 W̄_{n+1,m-1},   D_y W̄_nm =  f1 V̄_{n+1,m+1} + f2 V̄_{n+1,m-1}
//   D_z V̄_nm = -f3 V̄_{n+1,m},                      D_z W̄_nm = -f3 W̄_{n+1,m}
// (m >= 1 for the middle rows; W̄_n0 = 0.)
double k_factor(int n) { return (2.0 * n + 1.0) / (2.0 * n + 3.0); }
double g_factor(int n) { return std::sqrt(k_factor(n) * (n + 1.0) * (n + 2.0) / 2.0); }
double f1_factor(int n, int m) { return 0.5 * std::sqrt(k_factor(n) * (n + m + 1.0) * (n + m + 2.0)); }
double f2_factor(int n, int m) {
  // δ = 2 at m = 1: (2 - δ_0m)/(2 - δ_0,m-1) = 2/1 (the inverted ratio, δ = 1/2, is wrong).
  const double delta = m == 1 ? 2.0 : 1.0;
  return 0.5 * std::sqrt(delta * k_factor(n) * (n - m + 1.0) * (n - m + 2.0));
}
double f3_factor(int n, int m) { return std::sqrt(k_factor(n) * (n - m + 1.0) * (n + m + 1.0)); }

}  // namespace

namespace {

// A consistent field and a truncation it holds (degree within the field and kMaxDegree, order
// within the degree); the error names the offending argument.
core::Result<bool> check_field_and_truncation(const GravityField& field, int degree, int order) {
  if (!(field.gm > 0.0) || !std::isfinite(field.gm)) return core::Error{"field.gm", "must be finite and > 0"};
  if (!(field.radius > 0.0) || !std::isfinite(field.radius)) {
    return core::Error{"field.radius", "must be finite and > 0"};
  }
  if (field.max_degree < 0 || field.c_bar.size() < GravityField::coefficient_count(field.max_degree) ||
      field.s_bar.size() < GravityField::coefficient_count(field.max_degree)) {
    return core::Error{"field", "coefficient arrays do not hold degrees 0..max_degree"};
  }
  if (degree < 0 || degree > field.max_degree) {
    return core::Error{"degree", "must be in [0, " + std::to_string(field.max_degree) + "] (the field's max_degree), got " +
                                     std::to_string(degree)};
  }
  if (degree > SphericalHarmonicGravity::kMaxDegree) {
    return core::Error{"degree", "must be <= " + std::to_string(SphericalHarmonicGravity::kMaxDegree) + ", got " +
                                     std::to_string(degree)};
  }
  if (order < 0 || order > degree) {
    return core::Error{"order", "must be in [0, degree = " + std::to_string(degree) + "], got " + std::to_string(order)};
  }
  return true;
}

}  // namespace

core::Result<SphericalHarmonicGravity> SphericalHarmonicGravity::create(const GravityField& field, int degree,
                                                                         int order) {
  if (auto ok = check_field_and_truncation(field, degree, order); !ok) return ok.error();
  SphericalHarmonicGravity g;
  g.gm_ = field.gm;
  g.radius_ = field.radius;
  g.degree_ = degree;
  g.order_ = order;
  const std::size_t total = g.lay_out_rows();
  // Built as separate arrays, packed row by row at the end.
  UnpackedArrays arrays(kRowArrays, std::vector<double>(total, 0.0));
  g.f1_.assign(total, 0.0);
  g.f2_.assign(total, 0.0);
  g.f3_.assign(total, 0.0);
  g.sectorial_.assign(static_cast<std::size_t>(g.row_count()), 0.0);
  g.subdiagonal_.assign(static_cast<std::size_t>(g.row_count()), 0.0);
  g.compute_recursion_factors(arrays);
  g.compute_derivative_factors();
  g.fold_derivatives_into_coefficients(field, arrays);
  g.pack_rows(arrays, total);
  g.v_rows_.assign(3 * g.row_stride_, 0.0);
  g.w_rows_.assign(3 * g.row_stride_, 0.0);
  g.sums_.assign(9 * g.row_stride_, 0.0);
  return g;
}

// Rows j = 0..N+2 (the gradient needs N+2), row j holding orders k = 0..min(j, M+2); returns the
// number of (j, k) entries.
std::size_t SphericalHarmonicGravity::lay_out_rows() {
  const int n_rows = row_count();
  const int k_cap = order_ + 2;
  row_stride_ = static_cast<std::size_t>(k_cap + 1);
  row_offset_.resize(static_cast<std::size_t>(n_rows) + 1);
  row_length_.resize(static_cast<std::size_t>(n_rows));
  std::size_t total = 0;
  for (int j = 0; j < n_rows; ++j) {
    row_offset_[static_cast<std::size_t>(j)] = total;
    row_length_[static_cast<std::size_t>(j)] = std::min(j, k_cap) + 1;
    total += static_cast<std::size_t>(std::min(j, k_cap) + 1);
  }
  row_offset_[static_cast<std::size_t>(n_rows)] = total;
  return total;
}

// Recursion coefficients (docs/algorithms/dynamics.md#normalised-cunningham-recursion): sectorial
// c_j, sub-diagonal sqrt(2j+1), general a_jk, b_jk.
void SphericalHarmonicGravity::compute_recursion_factors(UnpackedArrays& arrays) {
  const int k_cap = order_ + 2;
  auto at = [this](int j, int k) { return offset(j) + static_cast<std::size_t>(k); };
  std::vector<double>& rec_a = arrays[static_cast<std::size_t>(kRecA)];
  std::vector<double>& rec_b = arrays[static_cast<std::size_t>(kRecB)];
  for (int j = 1; j < row_count(); ++j) {
    const auto ju = static_cast<std::size_t>(j);
    sectorial_[ju] = j == 1 ? std::sqrt(3.0) : std::sqrt((2.0 * j + 1.0) / (2.0 * j));
    subdiagonal_[ju] = std::sqrt(2.0 * j + 1.0);
    // k = j-1 gives a = sqrt(2j+1), b = 0: the sub-diagonal term is the general one with
    // V̄_{j-2,j-1} = 0, which lets evaluate() run one loop over k <= j-1.
    for (int k = 0; k <= std::min(j - 1, k_cap); ++k) {
      const double nm = static_cast<double>(j - k) * static_cast<double>(j + k);
      rec_a[at(j, k)] = std::sqrt((2.0 * j - 1.0) * (2.0 * j + 1.0) / nm);
      rec_b[at(j, k)] =
          k == j - 1 ? 0.0 : std::sqrt((2.0 * j + 1.0) * (j + k - 1.0) * (j - k - 1.0) / (nm * (2.0 * j - 3.0)));
    }
  }
}

// Derivative factors of V̄_jk for the gradient (rows up to N+1).
void SphericalHarmonicGravity::compute_derivative_factors() {
  const int k_cap = order_ + 2;
  for (int j = 0; j <= degree_ + 1; ++j) {
    for (int k = 0; k <= std::min(j, k_cap); ++k) {
      const std::size_t e = offset(j) + static_cast<std::size_t>(k);
      f1_[e] = k == 0 ? g_factor(j) : f1_factor(j, k);
      f2_[e] = k == 0 ? 0.0 : f2_factor(j, k);
      f3_[e] = f3_factor(j, k);
    }
  }
}

// Fold the derivative relations into the coefficients: a/(GM/R^2) = Σ_nm C̄ D V̄_nm + S̄ D W̄_nm
// becomes Σ_jk (A_jk V̄_jk + B_jk W̄_jk) with j = n+1 (the acceleration sums of
// docs/algorithms/dynamics.md#normalised-cunningham-recursion, regrouped by (j, k)).
void SphericalHarmonicGravity::fold_derivatives_into_coefficients(const GravityField& field, UnpackedArrays& arrays) {
  auto at = [this](int j, int k) { return offset(j) + static_cast<std::size_t>(k); };
  auto array = [&arrays](RowArray q) -> std::vector<double>& { return arrays[static_cast<std::size_t>(q)]; };
  for (int n = 0; n <= degree_; ++n) {
    for (int m = 0; m <= std::min(n, order_); ++m) {
      const double c = field.c(n, m);
      const double s = m == 0 ? 0.0 : field.s(n, m);
      array(kUV)[at(n, m)] = c;
      array(kUW)[at(n, m)] = s;
      const int j = n + 1;
      if (m == 0) {
        const double gn = g_factor(n);
        array(kAxV)[at(j, 1)] -= gn * c;
        array(kAyW)[at(j, 1)] -= gn * c;
        array(kAzV)[at(j, 0)] -= f3_factor(n, 0) * c;
        continue;
      }
      const double f1 = f1_factor(n, m);
      const double f2 = f2_factor(n, m);
      const double f3 = f3_factor(n, m);
      array(kAxV)[at(j, m + 1)] -= f1 * c;
      array(kAxW)[at(j, m + 1)] -= f1 * s;
      array(kAyV)[at(j, m + 1)] += f1 * s;
      array(kAyW)[at(j, m + 1)] -= f1 * c;
      array(kAxV)[at(j, m - 1)] += f2 * c;
      array(kAxW)[at(j, m - 1)] += f2 * s;  // multiplies W̄_j0 = 0 when m = 1
      array(kAyV)[at(j, m - 1)] += f2 * s;
      array(kAyW)[at(j, m - 1)] -= f2 * c;
      array(kAzV)[at(j, m)] -= f3 * c;
      array(kAzW)[at(j, m)] -= f3 * s;
    }
  }
}

// The separate arrays interleaved row by row into packed_ (see the header).
void SphericalHarmonicGravity::pack_rows(const UnpackedArrays& arrays, std::size_t total) {
  packed_.assign(kRowArrays * total, 0.0);
  for (int j = 0; j < row_count(); ++j) {
    for (int q = 0; q < kRowArrays; ++q) {
      double* dst = packed_.data() + kRowArrays * offset(j) + static_cast<std::size_t>(q * row_length(j));
      const double* src = arrays[static_cast<std::size_t>(q)].data() + offset(j);
      std::copy(src, src + row_length(j), dst);
    }
  }
}

namespace {

// Geometry of one evaluation point (docs/algorithms/dynamics.md#normalised-cunningham-recursion):
// x0 = Rx/r^2, ..., ρ = R^2/r^2, V̄_00 = R/r.
struct Geometry {
  double x0, y0, z0, rho, v00;
};

Geometry geometry(const Eigen::Vector3d& r_itrf, double big_r) {
  const double r2 = r_itrf.squaredNorm();
  return {big_r * r_itrf.x() / r2, big_r * r_itrf.y() / r2, big_r * r_itrf.z() / r2, big_r * big_r / r2,
          big_r / std::sqrt(r2)};
}

// The two last entries of row j (k = j-1 and k = j), when within k_end:
//   sub-diagonal V̄_{j,j-1} = sqrt(2j+1) z0 V̄_{j-1,j-1};
//   sectorial V̄_jj + iW̄_jj = c_j (x0 + i y0)(V̄ + iW̄)_{j-1,j-1}.
inline void edge_terms(int j, int k_end, const Geometry& p, double subdiagonal, double sectorial,
                       const double* v1, const double* w1, double* v, double* w) {
  if (j - 1 <= k_end) {
    const double s = subdiagonal * p.z0;
    v[j - 1] = s * v1[j - 1];
    w[j - 1] = s * w1[j - 1];
  }
  if (j <= k_end) {
    v[j] = sectorial * (p.x0 * v1[j - 1] - p.y0 * w1[j - 1]);
    w[j] = sectorial * (p.x0 * w1[j - 1] + p.y0 * v1[j - 1]);
  }
}

// General term V̄_jk = a_jk z0 V̄_{j-1,k} - b_jk ρ V̄_{j-2,k} for k = 0..count-1 (k <= j-2), W̄ alike.
inline void general_terms(int count, const double* __restrict a, const double* __restrict b, double z0, double rho,
                          const double* __restrict v1, const double* __restrict w1, const double* __restrict v2,
                          const double* __restrict w2, double* __restrict v, double* __restrict w) {
  for (int k = 0; k < count; ++k) {
    const double az = a[k] * z0;
    const double br = b[k] * rho;
    v[k] = az * v1[k] - br * v2[k];
    w[k] = az * w1[k] - br * w2[k];
  }
}

// Recursion and accumulation fused for the general terms of one row (k = 0..count-1): V̄/W̄ stay
// in registers between the two, and the loop streams the row's packed coefficients once.
template <bool kWithAcceleration, bool kWithPotential>
inline void general_terms_and_sums(int count, const double* __restrict block, int length, double z0, double rho,
                                   const double* __restrict v1, const double* __restrict w1,
                                   const double* __restrict v2, const double* __restrict w2, double* __restrict v,
                                   double* __restrict w, double* __restrict sx, double* __restrict sy,
                                   double* __restrict sz, double* __restrict su) {
  const double* __restrict a = block;
  const double* __restrict b = block + length;
  const double* __restrict axv = block + 2 * length;
  const double* __restrict axw = block + 3 * length;
  const double* __restrict ayv = block + 4 * length;
  const double* __restrict ayw = block + 5 * length;
  const double* __restrict azv = block + 6 * length;
  const double* __restrict azw = block + 7 * length;
  const double* __restrict uv = block + 8 * length;
  const double* __restrict uw = block + 9 * length;
  for (int k = 0; k < count; ++k) {
    const double az = a[k] * z0;
    const double br = b[k] * rho;
    const double vk = az * v1[k] - br * v2[k];
    const double wk = az * w1[k] - br * w2[k];
    v[k] = vk;
    w[k] = wk;
    if constexpr (kWithAcceleration) {
      sx[k] += axv[k] * vk + axw[k] * wk;
      sy[k] += ayv[k] * vk + ayw[k] * wk;
      sz[k] += azv[k] * vk + azw[k] * wk;
    }
    if constexpr (kWithPotential) su[k] += uv[k] * vk + uw[k] * wk;
  }
}

// Gradient contributions of one row j of the acceleration's linear forms, orders k = 1..k_end:
// D_l V̄_jk and D_l W̄_jk from row j+1 (vn, wn; see the relations at the top of this file), then
// sums[3i+l][k] += A_i,V D_l V̄ + A_i,W D_l W̄. Nine named streams so that the loop vectorises.
inline void gradient_terms(int k_end, const double* __restrict f1, const double* __restrict f2,
                           const double* __restrict f3, const double* const av[3], const double* const aw[3],
                           const double* __restrict vn, const double* __restrict wn, double* __restrict sums,
                           std::size_t stride) {
  const double* __restrict axv = av[0];
  const double* __restrict ayv = av[1];
  const double* __restrict azv = av[2];
  const double* __restrict axw = aw[0];
  const double* __restrict ayw = aw[1];
  const double* __restrict azw = aw[2];
  double* __restrict sxx = sums;
  double* __restrict sxy = sums + stride;
  double* __restrict sxz = sums + 2 * stride;
  double* __restrict syx = sums + 3 * stride;
  double* __restrict syy = sums + 4 * stride;
  double* __restrict syz = sums + 5 * stride;
  double* __restrict szx = sums + 6 * stride;
  double* __restrict szy = sums + 7 * stride;
  double* __restrict szz = sums + 8 * stride;
  for (int k = 1; k <= k_end; ++k) {
    const double vp = vn[k + 1];
    const double wp = wn[k + 1];
    const double vm = vn[k - 1];
    const double wm = wn[k - 1];
    const double dxv = -f1[k] * vp + f2[k] * vm;
    const double dyv = -f1[k] * wp - f2[k] * wm;
    const double dzv = -f3[k] * vn[k];
    const double dxw = -f1[k] * wp + f2[k] * wm;
    const double dyw = f1[k] * vp + f2[k] * vm;
    const double dzw = -f3[k] * wn[k];
    sxx[k] += axv[k] * dxv + axw[k] * dxw;
    sxy[k] += axv[k] * dyv + axw[k] * dyw;
    sxz[k] += axv[k] * dzv + axw[k] * dzw;
    syx[k] += ayv[k] * dxv + ayw[k] * dxw;
    syy[k] += ayv[k] * dyv + ayw[k] * dyw;
    syz[k] += ayv[k] * dzv + ayw[k] * dzw;
    szx[k] += azv[k] * dxv + azw[k] * dxw;
    szy[k] += azv[k] * dyv + azw[k] * dyw;
    szz[k] += azv[k] * dzv + azw[k] * dzw;
  }
}

// Σ_k s[k], k = 0..k_cap in increasing order: the per-order partial sums of a linear form.
double sum_over_orders(const double* s, int k_cap) {
  double sum = 0.0;
  for (int k = 0; k <= k_cap; ++k) sum += s[k];
  return sum;
}

// The same for the three acceleration components in one pass (three independent sums).
Eigen::Vector3d sum_over_orders(const double* sx, const double* sy, const double* sz, int k_cap) {
  double ax = 0.0;
  double ay = 0.0;
  double az = 0.0;
  for (int k = 0; k <= k_cap; ++k) {
    ax += sx[k];
    ay += sy[k];
    az += sz[k];
  }
  return {ax, ay, az};
}

}  // namespace

template <bool kWithAcceleration, bool kWithPotential>
void SphericalHarmonicGravity::evaluate(const Eigen::Vector3d& r_itrf, Eigen::Vector3d* a_itrf, double* potential) {
  const Geometry p = geometry(r_itrf, radius_);
  // The acceleration needs V̄/W̄ one degree and one order beyond the field (D raises n by 1).
  const int last_row = kWithAcceleration ? degree_ + 1 : degree_;
  const int k_cap = kWithAcceleration ? order_ + 1 : order_;
  const std::size_t stride = row_stride_;
  double* sx = sums_.data();
  double* sy = sx + stride;
  double* sz = sy + stride;
  double* su = sz + stride;
  std::fill(sums_.begin(), sums_.begin() + static_cast<std::ptrdiff_t>(4 * stride), 0.0);

  // Rolling rows: current j, j-1, j-2. Invariant: after row i, entry i+1 of its buffer is 0
  // (when within the orders used), so row i+2's sub-diagonal follows the general formula.
  double* v = v_rows_.data();
  double* w = w_rows_.data();
  double* v1 = v + stride;
  double* w1 = w + stride;
  double* v2 = v1 + stride;
  double* w2 = w1 + stride;
  v[0] = p.v00;
  w[0] = 0.0;
  v[1] = 0.0;  // stride = M+3 >= 3
  w[1] = 0.0;
  v1[0] = 0.0;  // "row -1", read with b = 0 by row 1; zeroed so stale values never leak in
  w1[0] = 0.0;
  for (int j = 0; j <= last_row; ++j) {
    const int k_end = std::min(j, k_cap);
    if (j > 0) {
      // Sectorial V̄_jj + iW̄_jj = c_j (x0 + i y0)(V̄ + iW̄)_{j-1,j-1}, the normalised recursion.
      if (j <= k_end) {
        const double c = sectorial_[static_cast<std::size_t>(j)];
        v[j] = c * (p.x0 * v1[j - 1] - p.y0 * w1[j - 1]);
        w[j] = c * (p.x0 * w1[j - 1] + p.y0 * v1[j - 1]);
      }
      general_terms_and_sums<kWithAcceleration, kWithPotential>(std::min(j - 1, k_end) + 1, row_array(j, kRecA),
                                                                row_length(j), p.z0, p.rho, v1, w1, v2, w2, v, w,
                                                                sx, sy, sz, su);
      if (j + 1 <= k_cap) {
        v[j + 1] = 0.0;
        w[j + 1] = 0.0;
      }
    }
    // Row 0 and the sectorial term are not in the fused loop: accumulate them here.
    if (j <= k_end) {
      const auto e = static_cast<std::size_t>(j);
      if constexpr (kWithAcceleration) {
        sx[j] += row_array(j, kAxV)[e] * v[j] + row_array(j, kAxW)[e] * w[j];
        sy[j] += row_array(j, kAyV)[e] * v[j] + row_array(j, kAyW)[e] * w[j];
        sz[j] += row_array(j, kAzV)[e] * v[j] + row_array(j, kAzW)[e] * w[j];
      }
      if constexpr (kWithPotential) su[j] += row_array(j, kUV)[e] * v[j] + row_array(j, kUW)[e] * w[j];
    }
    // Rotate: the current row becomes j-1, j-1 becomes j-2, the old j-2 buffer is reused.
    double* const v_old = v2;
    double* const w_old = w2;
    v2 = v1;
    w2 = w1;
    v1 = v;
    w1 = w;
    v = v_old;
    w = w_old;
  }

  if constexpr (kWithAcceleration) {
    const double scale = gm_ / (radius_ * radius_);  // a = (GM/R^2)(ẍ, ÿ, z̈)
    const Eigen::Vector3d sum = sum_over_orders(sx, sy, sz, k_cap);
    *a_itrf = Eigen::Vector3d(scale * sum.x(), scale * sum.y(), scale * sum.z());
  }
  if constexpr (kWithPotential) {
    *potential = gm_ / radius_ * sum_over_orders(su, k_cap);  // U = (GM/R) Σ (C̄ V̄ + S̄ W̄)
  }
}

Eigen::Vector3d SphericalHarmonicGravity::acceleration(const Eigen::Vector3d& r_itrf) {
  Eigen::Vector3d a_itrf;
  evaluate<true, false>(r_itrf, &a_itrf, nullptr);
  return a_itrf;
}

double SphericalHarmonicGravity::potential(const Eigen::Vector3d& r_itrf) {
  double u = 0.0;
  evaluate<false, true>(r_itrf, nullptr, &u);
  return u;
}

GravityAccelerationPotential SphericalHarmonicGravity::acceleration_and_potential(const Eigen::Vector3d& r_itrf) {
  GravityAccelerationPotential out{Eigen::Vector3d::Zero(), 0.0};
  evaluate<true, true>(r_itrf, &out.a_itrf, &out.potential);
  return out;
}

Eigen::Matrix3d SphericalHarmonicGravity::gradient(const Eigen::Vector3d& r_itrf) {
  const Geometry p = geometry(r_itrf, radius_);
  const int k_cap = order_ + 2;  // V̄/W̄ orders needed: two derivatives raise m by up to 2
  const int k_acc = order_ + 1;  // orders of the acceleration's linear forms
  const std::size_t stride = row_stride_;
  std::fill(sums_.begin(), sums_.end(), 0.0);
  // sums_ block 3*i + l accumulates ∂a_i/∂x_l per order.
  double* __restrict s = sums_.data();

  double* v = v_rows_.data();
  double* w = w_rows_.data();
  double* v1 = v + stride;
  double* w1 = w + stride;
  double* v2 = v1 + stride;
  double* w2 = w1 + stride;
  // Row 0 goes into the "j-1" buffer: the loop below computes row `row` into v/w.
  v1[0] = p.v00;
  w1[0] = 0.0;
  for (int row = 1; row <= degree_ + 2; ++row) {
    const int k_end_row = std::min(row, k_cap);
    const int general = std::min(row - 2, k_end_row) + 1;
    if (general > 0) {
      general_terms(general, row_array(row, kRecA), row_array(row, kRecB), p.z0, p.rho, v1, w1, v2, w2, v, w);
    }
    edge_terms(row, k_end_row, p, subdiagonal_[static_cast<std::size_t>(row)],
               sectorial_[static_cast<std::size_t>(row)], v1, w1, v, w);

    // Differentiate the acceleration's linear form of row j = row-1 with row `row` (one degree up).
    const int j = row - 1;
    const int k_end = std::min(j, k_acc);
    const double* vn = v;
    const double* wn = w;
    const std::size_t o = offset(j);
    const double* f1 = f1_.data() + o;
    const double* f2 = f2_.data() + o;
    const double* f3 = f3_.data() + o;
    const double* const av[3] = {row_array(j, kAxV), row_array(j, kAyV), row_array(j, kAzV)};
    const double* const aw[3] = {row_array(j, kAxW), row_array(j, kAyW), row_array(j, kAzW)};
    {
      // k = 0: W̄_j0 = 0, D V̄_j0 = (-g V̄_{j+1,1}, -g W̄_{j+1,1}, -f3 V̄_{j+1,0}).
      const double d[3] = {-f1[0] * vn[1], -f1[0] * wn[1], -f3[0] * vn[0]};
      for (int i = 0; i < 3; ++i) {
        for (int l = 0; l < 3; ++l) s[static_cast<std::size_t>(3 * i + l) * stride] += av[i][0] * d[l];
      }
    }
    if (k_end >= 1) {
      gradient_terms(k_end, f1, f2, f3, av, aw, vn, wn, s, stride);
    }
    double* const v_old = v2;
    double* const w_old = w2;
    v2 = v1;
    w2 = w1;
    v1 = v;
    w1 = w;
    v = v_old;
    w = w_old;
  }

  Eigen::Matrix3d g;
  const double scale = gm_ / (radius_ * radius_ * radius_);  // ∂a/∂r = (GM/R^3) Σ A D V̄
  for (int i = 0; i < 3; ++i) {
    for (int l = 0; l < 3; ++l) {
      const double* block = s + static_cast<std::size_t>(3 * i + l) * stride;
      double sum = 0.0;
      for (int k = 0; k <= k_acc; ++k) sum += block[k];
      g(i, l) = scale * sum;
    }
  }
  return g;
}

}  // namespace visors::dynamics
