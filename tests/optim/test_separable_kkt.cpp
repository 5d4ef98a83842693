// The Schur-complement KKT solve for separable G against a dense LU of the full KKT matrix
// [0 A' G'; A 0 0; G 0 -W^2] (Eigen's FullPivLU, an independent factorisation).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <Eigen/LU>

#include "visors/optim/cone.hpp"
#include "visors/optim/separable_kkt.hpp"

namespace {

using visors::optim::ConeProduct;
using visors::optim::NtScaling;
using visors::optim::SeparableKkt;

// K = R+^2 x Q^4 x Q^3 (m = n = 9), p = 3; G = diag(g) with its columns permuted.
struct Fixture {
  ConeProduct cone{2, {4, 3}};
  NtScaling nt{cone};
  int m = 9, p = 3;
  std::vector<int> column{4, 0, 8, 1, 6, 2, 7, 3, 5};
  Eigen::VectorXd g{{-1.0, 2.5, -0.5, 1.5, -3.0, 0.75, -1.25, 2.0, -0.4}};
  Eigen::MatrixXd A;
  Eigen::MatrixXd W2;  // W^2 as a dense matrix, from apply_square on unit vectors

  explicit Fixture(bool rank_deficient) {
    std::mt19937 rng(7);
    std::normal_distribution<double> normal;
    A = Eigen::MatrixXd::NullaryExpr(p, m, [&] { return normal(rng); });
    if (rank_deficient) A.row(2) = A.row(0) - 2.0 * A.row(1);
    // Interior s, z: orthant positive, each SOC head above the norm of its tail.
    std::vector<double> s{0.5, 2.0, 3.0, 1.0, -1.5, 0.7, 2.0, 0.3, -0.9};
    std::vector<double> z{1.5, 0.1, 2.2, 0.3, 0.8, -1.0, 1.7, -0.6, 0.2};
    std::vector<double> lambda(9);
    EXPECT_TRUE(nt.update(s.data(), z.data(), lambda.data()));
    W2.resize(m, m);
    std::vector<double> e(9), col(9);
    for (int j = 0; j < m; ++j) {
      std::fill(e.begin(), e.end(), 0.0);
      e[static_cast<std::size_t>(j)] = 1.0;
      nt.apply_square(e.data(), col.data());
      for (int i = 0; i < m; ++i) W2(i, j) = col[static_cast<std::size_t>(i)];
    }
  }
  [[nodiscard]] Eigen::MatrixXd G() const {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(m, m);
    for (int r = 0; r < m; ++r) out(r, column[static_cast<std::size_t>(r)]) = g(r);
    return out;
  }
  [[nodiscard]] Eigen::MatrixXd kkt() const {
    const int n = m;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + p + m, n + p + m);
    K.block(0, n, n, p) = A.transpose();
    K.block(0, n + p, n, m) = G().transpose();
    K.block(n, 0, p, n) = A;
    K.block(n + p, 0, m, n) = G();
    K.block(n + p, n + p, m, m) = -W2;
    return K;
  }
  void load(SeparableKkt& kkt) const {
    for (int r = 0; r < m; ++r) kkt.set_row(r, column[static_cast<std::size_t>(r)], g(r));
    kkt.clear_equalities();
    for (int i = 0; i < p; ++i) {
      for (int r = 0; r < m; ++r) kkt.set_equality_entry(i, r, A(i, column[static_cast<std::size_t>(r)]));
    }
  }
};

TEST(SeparableKkt, SolveMatchesDenseLuOfTheFullSystem) {
  const Fixture f(false);
  SeparableKkt kkt(f.m, f.p);
  f.load(kkt);
  ASSERT_TRUE(kkt.factor(f.nt));
  Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(f.m + f.p + f.m, -2.0, 3.0).array().sin();
  Eigen::VectorXd out(rhs.size());
  kkt.solve(f.nt, rhs.data(), rhs.data() + f.m, rhs.data() + f.m + f.p, out.data(), out.data() + f.m,
            out.data() + f.m + f.p);
  const Eigen::VectorXd reference = f.kkt().fullPivLu().solve(rhs);
  // round-off times the condition of the KKT system; measured 4.9e-15 vs bound 1.8e-12 (2026-11)
  EXPECT_LT((out - reference).cwiseAbs().maxCoeff(), 1e-12 * reference.cwiseAbs().maxCoeff());
}

TEST(SeparableKkt, ResidualIsRhsMinusKktTimesSolution) {
  const Fixture f(false);
  SeparableKkt kkt(f.m, f.p);
  f.load(kkt);
  const int size = f.m + f.p + f.m;
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(size, 1.0, 4.0).array().cos();
  const Eigen::VectorXd o = Eigen::VectorXd::LinSpaced(size, -1.0, 1.0).array().exp();
  Eigen::VectorXd e(size);
  kkt.residual(f.nt, rhs.data(), rhs.data() + f.m, rhs.data() + f.m + f.p, o.data(), o.data() + f.m,
               o.data() + f.m + f.p, e.data(), e.data() + f.m, e.data() + f.m + f.p);
  const Eigen::VectorXd reference = rhs - f.kkt() * o;
  // loose-ish: measured 8.9e-16 (2026-11), bound 1e-13 ~110x above round-off
  EXPECT_LT((e - reference).cwiseAbs().maxCoeff(), 1e-13);
}

// A rank-deficient A makes S singular: factor() declines, the solver takes its general path.
TEST(SeparableKkt, RankDeficientEqualitiesAreRefused) {
  const Fixture f(true);
  SeparableKkt kkt(f.m, f.p);
  f.load(kkt);
  EXPECT_FALSE(kkt.factor(f.nt));
}

}  // namespace
