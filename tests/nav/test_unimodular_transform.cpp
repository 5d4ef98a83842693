// The reduction's transformation kept as a record of elementary operations: the explicit matrices
// it forms against hand computation and against the properties any unimodular Z must have
// (Z Z^-1 = I exactly, Z' Q Z = L' D L), and the vector transforms against those matrices, with
// and without folding the record into its base matrices.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "visors/nav/lambda_reduction.hpp"
#include "visors/nav/unimodular_transform.hpp"
#include "support/random_orthogonal.hpp"

namespace visors::nav {
namespace {

Eigen::MatrixXd formed(const UnimodularTransform& t) {
  AmbiguityMatrix Z;
  t.matrix(Z);
  return Z;
}

Eigen::MatrixXd formed_inverse_transpose(const UnimodularTransform& t) {
  AmbiguityMatrix Z_inv_t;
  t.inverse_transpose_matrix(Z_inv_t);
  return Z_inv_t;
}

Eigen::MatrixXd random_integers(Eigen::Index rows, Eigen::Index cols, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> value(-1000000, 1000000);
  Eigen::MatrixXd V(rows, cols);
  for (Eigen::Index c = 0; c < cols; ++c) {
    for (Eigen::Index r = 0; r < rows; ++r) V(r, c) = value(rng);
  }
  return V;
}

// Column 0 minus 2 x column 2, then columns 0 and 1 exchanged (worked by hand):
// I -> [1 0 0; 0 1 0; -2 0 1] -> [0 1 0; 1 0 0; 0 -2 1].
TEST(UnimodularTransform, FormsTheMatrixOfItsOperations) {
  UnimodularTransform t;
  t.reset(3);
  t.subtract(2, 0, 2.0);
  t.exchange(0, 1);
  Eigen::Matrix3d expected;
  expected << 0, 1, 0, 1, 0, 0, 0, -2, 1;
  EXPECT_EQ(formed(t), Eigen::MatrixXd(expected));
}

TEST(UnimodularTransform, InverseTransposeOfTheHandExample) {
  UnimodularTransform t;
  t.reset(3);
  t.subtract(2, 0, 2.0);
  t.exchange(0, 1);
  Eigen::Matrix3d Z;
  Z << 0, 1, 0, 1, 0, 0, 0, -2, 1;
  EXPECT_EQ(formed_inverse_transpose(t), Eigen::MatrixXd(Z.inverse().transpose()));
}

TEST(UnimodularTransform, ResetGivesTheIdentity) {
  UnimodularTransform t;
  t.reset(2);
  t.exchange(0, 1);
  t.reset(4);
  EXPECT_EQ(formed(t), Eigen::MatrixXd::Identity(4, 4));
}

// Decorrelations of random SPD matrices (eigenvalues log-spaced over [1e-6, 1]): n = 12 stays in
// the record; n = 44 does ~20,000 operations and folds the record several times.
class ReductionTransform : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    const int n = GetParam();
    std::mt19937_64 rng(300 + n);
    Eigen::VectorXd ev(n);
    for (int i = 0; i < n; ++i) ev(i) = std::pow(10.0, -6.0 + 6.0 * i / (n - 1));
    Q = test::spd_with_eigenvalues(test::haar_orthogonal(n, rng), ev);
    ASSERT_TRUE(decorrelate(Q, 1'000'000, dc, ws));
    Z = formed(dc.transform);
    Z_inv_t = formed_inverse_transpose(dc.transform);
    V = random_integers(n, 2, rng);
  }
  Eigen::MatrixXd Q, Z, Z_inv_t, V;
  Decorrelation dc;
  DecorrelationWorkspace ws;
};

TEST_P(ReductionTransform, FoldsOnlyWhenTheRecordIsFull) {
  EXPECT_EQ(dc.transform.operations() > kTransformRecordCapacity, GetParam() > 24) << dc.transform.operations();
}

TEST_P(ReductionTransform, MatrixTimesInverseIsExactlyTheIdentity) {
  EXPECT_EQ(Z * Z_inv_t.transpose(), Eigen::MatrixXd::Identity(Z.rows(), Z.cols()));
}

TEST_P(ReductionTransform, ReproducesTheDecorrelatedCovariance) {
  const Eigen::Index n = Z.rows();
  const Eigen::MatrixXd L = dc.L.topLeftCorner(n, n).triangularView<Eigen::UnitLower>();
  const Eigen::MatrixXd Q_z = Z.transpose() * Q * Z;
  EXPECT_LE((Q_z - L.transpose() * dc.d.head(n).asDiagonal() * L).norm(), 1e-9 * Q_z.norm());
}

TEST_P(ReductionTransform, TransposeOfIntegerVectorsIsExact) {
  Eigen::MatrixXd W = V;
  dc.transform.apply_transpose(W);
  EXPECT_EQ(W, Z.transpose() * V);
}

TEST_P(ReductionTransform, InverseTransposeOfIntegerVectorsIsExact) {
  Eigen::MatrixXd W = V;
  dc.transform.apply_inverse_transpose(W);
  EXPECT_EQ(W, Z_inv_t * V);
}

TEST_P(ReductionTransform, InverseTransposeUndoesTranspose) {
  Eigen::MatrixXd W = V;
  dc.transform.apply_transpose(W);
  dc.transform.apply_inverse_transpose(W);
  EXPECT_EQ(W, V);
}

INSTANTIATE_TEST_SUITE_P(Sizes, ReductionTransform, ::testing::Values(12, 44));

}  // namespace
}  // namespace visors::nav
