#include "visors/optim/separable_kkt.hpp"

#include <algorithm>
#include <cmath>

namespace visors::optim {

namespace {
// A Cholesky pivot below this fraction of the largest diagonal entry of S counts as singular:
// the solve would lose more than ~13 of 16 digits, and the general path (regularised LDL',
// dense LU) does better on a rank-deficient A.
constexpr double kRelativePivot = 1e-13;
}  // namespace

SeparableKkt::SeparableKkt(int m, int p)
    : m_(m),
      p_(p),
      column_(Eigen::VectorXi::Zero(m)),
      g_(Eigen::VectorXd::Ones(m)),
      g_inv_(Eigen::VectorXd::Ones(m)),
      ak_(RowMajor::Zero(m, p)),
      wak_(RowMajor::Zero(m, p)),
      s_(Eigen::MatrixXd::Zero(p, p)),
      llt_(p),
      row_a_(Eigen::VectorXd::Zero(m)),
      row_b_(Eigen::VectorXd::Zero(m)),
      eq_(Eigen::VectorXd::Zero(p)) {}

void SeparableKkt::set_row(int r, int column, double g) {
  column_(r) = column;
  g_(r) = g;
  g_inv_(r) = 1.0 / g;
}

void SeparableKkt::clear_equalities() { ak_.setZero(); }

bool SeparableKkt::factor(const NtScaling& nt) {
  for (int k = 0; k < nt.blocks(); ++k) {
    const auto offset = static_cast<Eigen::Index>(nt.block_start(k)) * p_;
    nt.apply_block_rows(k, ak_.data() + offset, wak_.data() + offset, p_);
  }
  // S = (W ak)'(W ak): the row-major m x p storage read as its column-major transpose.
  const Eigen::Map<const Eigen::MatrixXd> wak_t(wak_.data(), p_, m_);
  s_.noalias() = wak_t * wak_t.transpose();
  const double largest = p_ > 0 ? s_.diagonal().maxCoeff() : 1.0;
  llt_.compute(s_);  // reads the lower triangle only
  if (llt_.info() != Eigen::Success || !(largest > 0.0) || !std::isfinite(largest)) return false;
  const auto l_diagonal = llt_.matrixLLT().diagonal();
  return p_ == 0 || l_diagonal.cwiseAbs2().minCoeff() > kRelativePivot * largest;
}

void SeparableKkt::solve(const NtScaling& nt, const double* bx, const double* by, const double* bz, double* ox,
                         double* oy, double* oz) {
  for (int r = 0; r < m_; ++r) row_a_(r) = bx[column_(r)] * g_inv_(r);  // bxg
  nt.apply_square(row_a_.data(), row_b_.data());
  const Eigen::Map<const Eigen::VectorXd> bz_v(bz, m_);
  row_b_ += bz_v;
  eq_.noalias() = ak_.transpose() * row_b_;
  eq_ -= Eigen::Map<const Eigen::VectorXd>(by, p_);
  llt_.solveInPlace(eq_);
  Eigen::Map<Eigen::VectorXd>(oy, p_) = eq_;
  row_a_.noalias() -= ak_ * eq_;  // z = bxg - ak y
  Eigen::Map<Eigen::VectorXd>(oz, m_) = row_a_;
  nt.apply_square(row_a_.data(), row_b_.data());
  for (int r = 0; r < m_; ++r) ox[column_(r)] = (bz[r] + row_b_(r)) * g_inv_(r);
}

void SeparableKkt::residual(const NtScaling& nt, const double* bx, const double* by, const double* bz,
                            const double* ox, const double* oy, const double* oz, double* ex, double* ey,
                            double* ez) {
  // x rows: bx - A'y - G'z; column c_r of A'y is g_r (ak y)_r.
  row_a_.noalias() = ak_ * Eigen::Map<const Eigen::VectorXd>(oy, p_);
  for (int r = 0; r < m_; ++r) ex[column_(r)] = bx[column_(r)] - g_(r) * (row_a_(r) + oz[r]);
  // y rows: by - A x = by - ak'(G x); z rows: bz - (G x - W^2 z).
  for (int r = 0; r < m_; ++r) row_a_(r) = g_(r) * ox[column_(r)];
  eq_.noalias() = ak_.transpose() * row_a_;
  for (int i = 0; i < p_; ++i) ey[i] = by[i] - eq_(i);
  nt.apply_square(oz, row_b_.data());
  for (int r = 0; r < m_; ++r) ez[r] = bz[r] - (row_a_(r) - row_b_(r));
}

}  // namespace visors::optim
