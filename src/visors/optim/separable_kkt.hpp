#pragma once
// The KKT system of the conic solver,
//   [0 A' G'; A 0 0; G 0 -W^2] (x, y, z) = (bx, by, bz),
// when G is separable: each row r has a single entry g_r, in a column c_r of its own, so rows and
// columns pair one to one (m = n: the planners' minimum-fuel problems, ||dv_k|| <= t_k, and
// bound-constrained LPs). With ak the m x p matrix of rows A(:, c_r)' / g_r, eliminating x and z
// leaves the p x p Schur complement
//   S y = ak'(bz + W^2 bxg) - by,   S = ak' W^2 ak = (W ak)'(W ak),   bxg_r = bx(c_r) / g_r,
// then z = bxg - ak y and x(c_r) = (bz + W^2 z)_r / g_r. S is a sum of squares (positive definite
// when A has full row rank), factored by Cholesky without regularisation, so a solve is exact to
// roundoff and costs O(m p): two block applications of W^2 and two products with ak, against the
// O((n + p)^2) of the general LDL'. Nothing in this path squares the condition of W_k into a
// pivot the way forming G'W^-2 G would.
//
// Storage is sized by the constructor; nothing allocates afterwards.

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "visors/optim/cone.hpp"

namespace visors::optim {

class SeparableKkt {
 public:
  SeparableKkt() = default;
  /// Capacity for m rows (= columns) and p equality rows.
  SeparableKkt(int m, int p);

  /// Row r of G: its column and value (g != 0). Set every row, then clear_equalities() and the
  /// entries of A.
  void set_row(int r, int column, double g);
  void clear_equalities();
  /// A(i, c_r) = a, for the G row r paired with the column.
  void set_equality_entry(int i, int r, double a) { ak_(r, i) = a * g_inv_(r); }

  /// Forms and factors S for the scaling `nt`. False when S is not numerically positive definite
  /// (A rank deficient); the caller then uses its general factorisation.
  bool factor(const NtScaling& nt);
  /// (ox, oy, oz) = K^-1 (bx, by, bz) with the current factorisation (outputs distinct from inputs).
  void solve(const NtScaling& nt, const double* bx, const double* by, const double* bz, double* ox, double* oy,
             double* oz);
  /// (ex, ey, ez) = (bx, by, bz) - K (ox, oy, oz), the unregularised residual.
  void residual(const NtScaling& nt, const double* bx, const double* by, const double* bz, const double* ox,
                const double* oy, const double* oz, double* ex, double* ey, double* ez);

 private:
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  int m_ = 0;
  int p_ = 0;
  Eigen::VectorXi column_;  // c_r
  Eigen::VectorXd g_, g_inv_;
  RowMajor ak_;             // m x p, row r = A(:, c_r)' / g_r (row-major: a block's rows are contiguous)
  RowMajor wak_;            // W ak, then S = wak' wak
  Eigen::MatrixXd s_;       // p x p
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::VectorXd row_a_, row_b_, eq_;  // m, m, p scratch
};

}  // namespace visors::optim
