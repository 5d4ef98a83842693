// Single- to double-difference ambiguities
// (docs/algorithms/ambiguity-resolution.md#single-to-double-differences) against dense products G P
// G' built independently here, and the textbook DD cofactor of independent SDs.
#include "visors/nav/double_difference.hpp"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

namespace visors::nav {
namespace {

using Eigen::Index;

// A random symmetric positive definite n x n matrix: A A' + n I.
Eigen::MatrixXd random_spd(Index n, std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  Eigen::MatrixXd A(n, n);
  for (Index j = 0; j < n; ++j) {
    for (Index i = 0; i < n; ++i) A(i, j) = gauss(rng);
  }
  return A * A.transpose() + static_cast<double>(n) * Eigen::MatrixXd::Identity(n, n);
}

Eigen::VectorXd random_vector(Index n, std::mt19937_64& rng) {
  std::normal_distribution<double> gauss(0.0, 100.0);
  Eigen::VectorXd x(n);
  for (Index i = 0; i < n; ++i) x(i) = gauss(rng);
  return x;
}

// The differencing matrix D_m written out row by row: +1 at the satellite, -1 at the reference.
Eigen::MatrixXd dense_g(Index n_states, const std::vector<std::array<Index, 2>>& rows) {
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(static_cast<Index>(rows.size()), n_states);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    G(static_cast<Index>(r), rows[r][0]) = 1.0;
    G(static_cast<Index>(r), rows[r][1]) = -1.0;
  }
  return G;
}

// Filter [baseline 3, SD L1 of 5 satellites at 3..7, SD L2 of the same 5 at 8..12]; L1 reference
// state 5, L2 reference state 10 (a different satellite).
struct TwoGroups {
  static constexpr Index kStates = 13;
  std::array<Index, 4> l1_others{3, 4, 6, 7};
  std::array<Index, 4> l2_others{8, 9, 11, 12};
  std::vector<std::array<Index, 2>> rows{{3, 5}, {4, 5}, {6, 5}, {7, 5}, {8, 10}, {9, 10}, {11, 10}, {12, 10}};
};

DoubleDifferenceAmbiguities two_groups() {
  TwoGroups g;
  auto dd = DoubleDifferenceAmbiguities::create(20).value();
  EXPECT_TRUE(dd.reset(TwoGroups::kStates));
  EXPECT_TRUE(dd.add_group(5, g.l1_others));
  EXPECT_TRUE(dd.add_group(10, g.l2_others));
  return dd;
}

TEST(DoubleDifference, CreateRejectsZeroStatesNamingTheField) {
  const auto dd = DoubleDifferenceAmbiguities::create(0);
  ASSERT_FALSE(dd.ok());
  EXPECT_EQ(dd.error().field, "max_states");
}

TEST(DoubleDifference, TwoGroupsRowsAndReferences) {
  const auto dd = two_groups();
  ASSERT_EQ(dd.size(), 8);
  const TwoGroups g;
  for (Index r = 0; r < dd.size(); ++r) {
    EXPECT_EQ(dd.state_of(r), g.rows[static_cast<std::size_t>(r)][0]) << r;
    EXPECT_EQ(dd.reference_of(r), g.rows[static_cast<std::size_t>(r)][1]) << r;
  }
}

TEST(DoubleDifference, DenseGIsTheDoubleDifferenceMatrix) {
  const auto dd = two_groups();
  EXPECT_EQ(dd.G(), dense_g(TwoGroups::kStates, TwoGroups{}.rows));  // D_m row by row
}

TEST(DoubleDifference, AmbiguitiesEqualDenseGx) {
  auto dd = two_groups();
  std::mt19937_64 rng(11);
  const Eigen::VectorXd x = random_vector(TwoGroups::kStates, rng);
  ASSERT_TRUE(dd.evaluate(x, random_spd(TwoGroups::kStates, rng)));
  const Eigen::VectorXd expected = dense_g(TwoGroups::kStates, TwoGroups{}.rows) * x;  // a = D_m x
  EXPECT_LT((dd.a() - expected).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(DoubleDifference, CovarianceEqualsDenseGPGt) {
  auto dd = two_groups();
  std::mt19937_64 rng(12);
  const Eigen::MatrixXd P = random_spd(TwoGroups::kStates, rng);
  ASSERT_TRUE(dd.evaluate(random_vector(TwoGroups::kStates, rng), P));
  const Eigen::MatrixXd G = dense_g(TwoGroups::kStates, TwoGroups{}.rows);
  const Eigen::MatrixXd expected = G * P * G.transpose();  // Q = D_m P D_m'
  EXPECT_LT((dd.Q() - expected).cwiseAbs().maxCoeff(), 1e-12 * P.cwiseAbs().maxCoeff());
}

TEST(DoubleDifference, CrossCovarianceEqualsDensePGt) {
  auto dd = two_groups();
  std::mt19937_64 rng(13);
  const Eigen::MatrixXd P = random_spd(TwoGroups::kStates, rng);
  ASSERT_TRUE(dd.evaluate(random_vector(TwoGroups::kStates, rng), P));
  const Eigen::MatrixXd expected = P * dense_g(TwoGroups::kStates, TwoGroups{}.rows).transpose();  // P_xa, 6.1
  EXPECT_LT((dd.PGt() - expected).cwiseAbs().maxCoeff(), 1e-12 * P.cwiseAbs().maxCoeff());
}

TEST(DoubleDifference, CovarianceIsExactlySymmetric) {
  auto dd = two_groups();
  std::mt19937_64 rng(14);
  ASSERT_TRUE(dd.evaluate(random_vector(TwoGroups::kStates, rng), random_spd(TwoGroups::kStates, rng)));
  EXPECT_EQ(dd.Q(), dd.Q().transpose());  // Q exactly symmetric
}

// Independent SDs of variance s^2 give DD covariance s^2 (I + 1 1') per reference
// (docs/algorithms/gnss-measurements.md#double-differences; the DD cofactor 2 (I + 1 1') of
// tests/support/dd_geometry.hpp is this with s^2 = 2 sigma^2).
TEST(DoubleDifference, IndependentSdsGiveTheDdCofactor) {
  const double s2 = 0.04;  // SD ambiguity variance [cycles^2]
  auto dd = DoubleDifferenceAmbiguities::create(9).value();
  ASSERT_TRUE(dd.reset(9));
  const std::array<Index, 5> others{3, 4, 6, 7, 8};
  ASSERT_TRUE(dd.add_group(5, others));
  Eigen::MatrixXd P = Eigen::MatrixXd::Identity(9, 9);
  P.bottomRightCorner(6, 6) *= s2;
  ASSERT_TRUE(dd.evaluate(Eigen::VectorXd::Zero(9), P));
  const Eigen::MatrixXd expected = s2 * (Eigen::MatrixXd::Identity(5, 5) + Eigen::MatrixXd::Ones(5, 5));
  EXPECT_LT((dd.Q() - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(DoubleDifference, RejectsIndexOutOfRange) {
  auto dd = DoubleDifferenceAmbiguities::create(10).value();
  ASSERT_TRUE(dd.reset(8));
  const std::array<Index, 2> beyond{3, 8};  // 8 is not a state of an 8-state filter
  const std::array<Index, 2> negative{3, -1};
  EXPECT_FALSE(dd.add_group(4, beyond));
  EXPECT_FALSE(dd.add_group(4, negative));
  EXPECT_FALSE(dd.add_group(8, std::array<Index, 1>{3}));
  EXPECT_EQ(dd.size(), 0);
}

TEST(DoubleDifference, RejectsRepeatedSatellite) {
  auto dd = DoubleDifferenceAmbiguities::create(10).value();
  ASSERT_TRUE(dd.reset(10));
  EXPECT_FALSE(dd.add_group(4, std::array<Index, 3>{3, 5, 3}));
  EXPECT_EQ(dd.size(), 0);
}

TEST(DoubleDifference, RejectsSatelliteEqualToReference) {
  auto dd = DoubleDifferenceAmbiguities::create(10).value();
  ASSERT_TRUE(dd.reset(10));
  EXPECT_FALSE(dd.add_group(4, std::array<Index, 2>{3, 4}));
  EXPECT_EQ(dd.size(), 0);
}

// (e2 - e1) = (e2 - e0) - (e1 - e0): overlapping groups would make G rank deficient.
TEST(DoubleDifference, RejectsStateOfAnEarlierGroup) {
  auto dd = DoubleDifferenceAmbiguities::create(10).value();
  ASSERT_TRUE(dd.reset(10));
  ASSERT_TRUE(dd.add_group(0, std::array<Index, 2>{1, 2}));
  EXPECT_FALSE(dd.add_group(1, std::array<Index, 1>{3}));  // earlier satellite as reference
  EXPECT_FALSE(dd.add_group(3, std::array<Index, 1>{2}));  // earlier satellite
  EXPECT_FALSE(dd.add_group(3, std::array<Index, 1>{0}));  // earlier reference
  EXPECT_EQ(dd.size(), 2);
}

TEST(DoubleDifference, RejectsGroupBeyondCapacity) {
  auto dd = DoubleDifferenceAmbiguities::create(100).value();
  ASSERT_TRUE(dd.reset(100));
  std::vector<Index> others;
  for (Index i = 1; i <= kMaxAmbiguities + 1; ++i) others.push_back(i);
  EXPECT_FALSE(dd.add_group(0, others));  // 65 rows > kMaxAmbiguities
  others.pop_back();
  EXPECT_TRUE(dd.add_group(0, others));  // exactly kMaxAmbiguities
  EXPECT_EQ(dd.size(), kMaxAmbiguities);
}

TEST(DoubleDifference, ResetRejectsStatesBeyondCapacity) {
  auto dd = DoubleDifferenceAmbiguities::create(10).value();
  EXPECT_FALSE(dd.reset(11));
  EXPECT_FALSE(dd.reset(0));
  EXPECT_TRUE(dd.reset(10));
}

TEST(DoubleDifference, EvaluateRejectsSizeMismatch) {
  auto dd = two_groups();
  const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(TwoGroups::kStates, TwoGroups::kStates);
  EXPECT_FALSE(dd.evaluate(Eigen::VectorXd::Zero(TwoGroups::kStates - 1), P));
  EXPECT_FALSE(dd.evaluate(Eigen::VectorXd::Zero(TwoGroups::kStates), P.topLeftCorner(12, 13)));
}

TEST(DoubleDifference, ResetStartsAnEmptySet) {
  auto dd = two_groups();
  ASSERT_TRUE(dd.reset(TwoGroups::kStates));
  EXPECT_EQ(dd.size(), 0);
  EXPECT_TRUE(dd.add_group(3, std::array<Index, 1>{5}));  // 5 was the old L1 reference
}

}  // namespace
}  // namespace visors::nav
