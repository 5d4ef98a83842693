// Fixed-solution and hold updates (docs/algorithms/ambiguity-resolution.md#fixed-solution-update)
// against independent batch solutions: the equality-constrained least squares (KKT system, dense
// LU) for the exact conditioning, and the information form of the Kalman update for the hold; the
// fixed constraints of an integer solution; and an end-to-end SD filter state -> DD -> ILS -> fixed
// baseline.
#include "visors/nav/fixed_solution.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "support/dd_geometry.hpp"

namespace visors::nav {
namespace {

using Eigen::Index;
using Status = FixedSolutionUpdate::Status;

Eigen::MatrixXd random_matrix(Index rows, Index cols, std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  Eigen::MatrixXd A(rows, cols);
  for (Index j = 0; j < cols; ++j) {
    for (Index i = 0; i < rows; ++i) A(i, j) = gauss(rng);
  }
  return A;
}

Eigen::MatrixXd random_spd(Index n, std::mt19937_64& rng) {
  const Eigen::MatrixXd A = random_matrix(n, n, rng);
  return A * A.transpose() + static_cast<double>(n) * Eigen::MatrixXd::Identity(n, n);
}

struct Gaussian {
  Eigen::VectorXd x;
  Eigen::MatrixXd P;
};

// Conditional Gaussian as equality-constrained least squares: minimise (x - x0)' P^-1 (x - x0)
// subject to C x = z, by the KKT system [P^-1 C'; C 0] [x; l] = [P^-1 x0; z] (dense LU). The top-left
// block of the KKT inverse is the constrained covariance P - P C' (C P C')^-1 C P (block inverse).
Gaussian constrained_least_squares(const Gaussian& prior, const Eigen::MatrixXd& C, const Eigen::VectorXd& z) {
  const Index n = prior.x.size();
  const Index k = C.rows();
  const Eigen::MatrixXd P_inv = prior.P.inverse();
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + k, n + k);
  kkt.topLeftCorner(n, n) = P_inv;
  kkt.topRightCorner(n, k) = C.transpose();
  kkt.bottomLeftCorner(k, n) = C;
  Eigen::VectorXd rhs(n + k);
  rhs << P_inv * prior.x, z;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(kkt);
  return {lu.solve(rhs).head(n), lu.inverse().topLeftCorner(n, n)};
}

// Information form of the Kalman update with measurement z = C x + v, v ~ N(0, s I):
// P+ = (P^-1 + C' C / s)^-1, x+ = P+ (P^-1 x + C' z / s).
Gaussian information_update(const Gaussian& prior, const Eigen::MatrixXd& C, const Eigen::VectorXd& z, double s) {
  const Eigen::MatrixXd P_inv = prior.P.inverse();
  const Eigen::MatrixXd P_post = (P_inv + C.transpose() * C / s).inverse();
  return {P_post * (P_inv * prior.x + C.transpose() * z / s), P_post};
}

struct Problem {
  Gaussian prior;
  Eigen::MatrixXd C;
  Eigen::VectorXd z;
};

Problem random_problem(Index n, Index k, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Problem p;
  p.prior.P = random_spd(n, rng);
  p.prior.x = random_matrix(n, 1, rng);
  p.C = random_matrix(k, n, rng);
  p.z = random_matrix(k, 1, rng);
  return p;
}

Gaussian updated(const Problem& p, double variance, Status* status = nullptr) {
  auto update = FixedSolutionUpdate::create(p.prior.x.size(), p.C.rows()).value();
  Gaussian out = p.prior;
  const Status s = update.apply(out.x, out.P, p.C, p.z, variance);
  if (status != nullptr) *status = s;
  return out;
}

double max_abs(const Eigen::MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }

TEST(FixedSolution, CreateRejectsBadCapacityNamingTheField) {
  EXPECT_EQ(FixedSolutionUpdate::create(0).error().field, "max_states");
  EXPECT_EQ(FixedSolutionUpdate::create(5, 0).error().field, "max_constraints");
  EXPECT_EQ(FixedSolutionUpdate::create(5, kMaxAmbiguities + 1).error().field, "max_constraints");
}

TEST(FixedSolution, ExactUpdateReturnsOk) {
  Status status = Status::kSizeMismatch;
  updated(random_problem(10, 4, 1), 0.0, &status);
  EXPECT_EQ(status, Status::kOk);
}

TEST(FixedSolution, ExactUpdateMeanEqualsConstrainedLeastSquares) {
  const Problem p = random_problem(10, 4, 2);
  const Gaussian expected = constrained_least_squares(p.prior, p.C, p.z);  // KKT, dense LU
  EXPECT_LT(max_abs(updated(p, 0.0).x - expected.x), 1e-10 * (1.0 + max_abs(expected.x)));
}

TEST(FixedSolution, ExactUpdateCovarianceEqualsConstrainedLeastSquares) {
  const Problem p = random_problem(10, 4, 3);
  const Gaussian expected = constrained_least_squares(p.prior, p.C, p.z);  // KKT inverse block
  EXPECT_LT(max_abs(updated(p, 0.0).P - expected.P), 1e-10 * max_abs(p.prior.P));
}

TEST(FixedSolution, ExactUpdateSatisfiesTheConstraints) {
  const Problem p = random_problem(10, 4, 4);
  EXPECT_LT(max_abs(p.C * updated(p, 0.0).x - p.z), 1e-9);  // C x+ = z: conditioned on it
}

TEST(FixedSolution, ExactUpdateLeavesNoVarianceAlongTheConstraints) {
  const Problem p = random_problem(10, 4, 5);
  const Eigen::MatrixXd CPC = p.C * updated(p, 0.0).P * p.C.transpose();
  EXPECT_LT(max_abs(CPC), 1e-10 * max_abs(p.C * p.prior.P * p.C.transpose()));  // C P+ C' = 0
}

// Constraints on a middle block of states only, like an ambiguity fix (the filter's C has
// entries in its 24 SDCP ambiguity columns of 98): the update restricted to C's non-zero columns
// must still give the whole conditional, including the states C does not touch.
Problem block_problem(std::uint64_t seed) {
  Problem p = random_problem(12, 3, seed);
  p.C.leftCols(4).setZero();
  p.C.rightCols(3).setZero();
  return p;
}

TEST(FixedSolution, BlockConstraintMeanEqualsConstrainedLeastSquares) {
  const Problem p = block_problem(31);
  const Gaussian expected = constrained_least_squares(p.prior, p.C, p.z);  // KKT, dense LU
  EXPECT_LT(max_abs(updated(p, 0.0).x - expected.x), 1e-10 * (1.0 + max_abs(expected.x)));
}

TEST(FixedSolution, BlockConstraintCovarianceEqualsConstrainedLeastSquares) {
  const Problem p = block_problem(32);
  const Gaussian expected = constrained_least_squares(p.prior, p.C, p.z);  // KKT inverse block
  EXPECT_LT(max_abs(updated(p, 0.0).P - expected.P), 1e-10 * max_abs(p.prior.P));
}

TEST(FixedSolution, AllZeroConstraintIsNotPositiveDefinite) {
  Problem p = random_problem(6, 2, 33);
  p.C.setZero();  // C P C' = 0: nothing to condition on
  Status status = Status::kOk;
  updated(p, 0.0, &status);
  EXPECT_EQ(status, Status::kNotPositiveDefinite);
}

TEST(FixedSolution, HoldUpdateMeanEqualsInformationForm) {
  const Problem p = random_problem(10, 4, 6);
  const double s = 1e-3;  // RTKLIB VAR_HOLDAMB [cycles^2] (src/rtkpos.c, holdamb)
  const Gaussian expected = information_update(p.prior, p.C, p.z, s);
  EXPECT_LT(max_abs(updated(p, s).x - expected.x), 1e-9 * (1.0 + max_abs(expected.x)));
}

TEST(FixedSolution, HoldUpdateCovarianceEqualsInformationForm) {
  const Problem p = random_problem(10, 4, 7);
  const double s = 1e-3;
  const Gaussian expected = information_update(p.prior, p.C, p.z, s);
  EXPECT_LT(max_abs(updated(p, s).P - expected.P), 1e-9 * max_abs(p.prior.P));
}

// Consider states: the masked gain K = mask (P C' S^-1), the Joseph form
// (I - K C) P (I - K C)' + s K K' (valid for any gain), written out densely.
Gaussian dense_consider_update(const Problem& p, double s, const Eigen::VectorXd& mask) {
  const Eigen::MatrixXd S = p.C * p.prior.P * p.C.transpose() + s * Eigen::MatrixXd::Identity(p.C.rows(), p.C.rows());
  const Eigen::MatrixXd K = mask.asDiagonal() * (p.prior.P * p.C.transpose() * S.inverse());
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(p.prior.x.size(), p.prior.x.size()) - K * p.C;
  return {p.prior.x + K * (p.z - p.C * p.prior.x), A * p.prior.P * A.transpose() + s * K * K.transpose()};
}

Gaussian consider_updated(const Problem& p, double s, const Eigen::VectorXd& mask) {
  auto update = FixedSolutionUpdate::create(p.prior.x.size(), p.C.rows()).value();
  Gaussian out = p.prior;
  EXPECT_EQ(update.apply(out.x, out.P, p.C, p.z, s, mask), Status::kOk);
  return out;
}

Eigen::VectorXd mask_without(Index n, Index first, Index count) {
  Eigen::VectorXd mask = Eigen::VectorXd::Ones(n);
  mask.segment(first, count).setZero();
  return mask;
}

TEST(FixedSolution, ConsiderStatesAreHeld) {
  const Problem p = random_problem(10, 4, 31);
  const Gaussian out = consider_updated(p, 1e-3, mask_without(10, 2, 3));
  EXPECT_EQ(out.x.segment(2, 3), p.prior.x.segment(2, 3));
}

TEST(FixedSolution, ConsiderHoldCovarianceEqualsDenseJoseph) {
  const Problem p = random_problem(10, 4, 32);
  const Eigen::VectorXd mask = mask_without(10, 2, 3);
  EXPECT_LT(max_abs(consider_updated(p, 1e-3, mask).P - dense_consider_update(p, 1e-3, mask).P), 1e-9 * max_abs(p.prior.P));
}

TEST(FixedSolution, ConsiderExactMeanEqualsDenseJoseph) {
  const Problem p = random_problem(10, 4, 33);
  const Eigen::VectorXd mask = mask_without(10, 6, 2);
  const Gaussian expected = dense_consider_update(p, 0.0, mask);
  EXPECT_LT(max_abs(consider_updated(p, 0.0, mask).x - expected.x), 1e-9 * (1.0 + max_abs(expected.x)));
}

TEST(FixedSolution, AllOnesMaskIsTheOptimalUpdate) {
  const Problem p = random_problem(10, 4, 34);
  EXPECT_EQ(consider_updated(p, 1e-3, Eigen::VectorXd::Ones(10)).P, updated(p, 1e-3).P);
}

TEST(FixedSolution, MaskOfTheWrongSizeIsASizeMismatch) {
  const Problem p = random_problem(10, 4, 35);
  auto update = FixedSolutionUpdate::create(10, 4).value();
  Gaussian out = p.prior;
  EXPECT_EQ(update.apply(out.x, out.P, p.C, p.z, 1e-3, Eigen::VectorXd::Ones(9)), Status::kSizeMismatch);
}

// The input P carries a round-off asymmetry (as a filter's time update may leave): P+ comes out
// exactly symmetric all the same.
TEST(FixedSolution, CovarianceComesOutExactlySymmetric) {
  Problem p = random_problem(12, 5, 8);
  p.prior.P(3, 7) += 1e-14 * p.prior.P(3, 7);
  const Eigen::MatrixXd P_exact = updated(p, 0.0).P;
  const Eigen::MatrixXd P_hold = updated(p, 1e-3).P;
  EXPECT_EQ(P_exact, P_exact.transpose());
  EXPECT_EQ(P_hold, P_hold.transpose());
}

TEST(FixedSolution, ExactCovarianceStaysPositiveSemidefinite) {
  const Problem p = random_problem(12, 5, 9);
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(updated(p, 0.0).P).eigenvalues();
  // k = 5 eigenvalues are zero up to round-off; none may be significantly negative.
  EXPECT_GT(eigenvalues.minCoeff(), -1e-12 * max_abs(p.prior.P));
}

TEST(FixedSolution, HoldCovarianceStaysPositiveDefinite) {
  const Problem p = random_problem(12, 5, 10);
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(updated(p, 1e-3).P).eigenvalues();
  EXPECT_GT(eigenvalues.minCoeff(), 0.0);  // s > 0 keeps P positive definite
}

// The status tests check x and P bit for bit (NaN included): a refused update must not touch them.
bool same_bits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), static_cast<std::size_t>(a.size()) * sizeof(double)) == 0;
}

void expect_refused(const Problem& p, double variance, Status expected) {
  auto update = FixedSolutionUpdate::create(20).value();
  Gaussian state = p.prior;
  EXPECT_EQ(update.apply(state.x, state.P, p.C, p.z, variance), expected);
  EXPECT_TRUE(same_bits(state.x, p.prior.x));
  EXPECT_TRUE(same_bits(state.P, p.prior.P));
}

TEST(FixedSolution, NegativeDefiniteCovarianceIsNotPositiveDefinite) {
  Problem p = random_problem(6, 3, 11);
  p.prior.P = -p.prior.P;
  expect_refused(p, 0.0, Status::kNotPositiveDefinite);
}

// Positive diagonal, eigenvalues 3 and -1 in the constrained block: Cholesky fails at its second pivot.
TEST(FixedSolution, IndefiniteCovarianceIsNotPositiveDefinite) {
  Problem p = random_problem(6, 2, 11);
  p.prior.P = Eigen::MatrixXd::Identity(6, 6);
  p.prior.P(0, 1) = p.prior.P(1, 0) = 2.0;
  p.C = Eigen::MatrixXd::Identity(2, 6);
  expect_refused(p, 0.0, Status::kNotPositiveDefinite);
}

TEST(FixedSolution, RedundantExactConstraintsAreNotPositiveDefinite) {
  Problem p = random_problem(6, 3, 12);
  p.C.row(2) = p.C.row(0) + p.C.row(1);  // rank 2: C P C' singular with s = 0
  expect_refused(p, 0.0, Status::kNotPositiveDefinite);
}

// Dependent to 1e-7: C P C' has a smallest eigenvalue ~1e-14 of its largest, positive (well above
// round-off), so Cholesky succeeds; its squared pivot is below kRelativePivot = 1e-13 of the
// largest diagonal, where the gain would keep fewer than ~3 digits.
TEST(FixedSolution, NearlyRedundantExactConstraintsAreNotPositiveDefinite) {
  Problem p = random_problem(6, 3, 12);
  p.C.row(2) = p.C.row(0) + p.C.row(1) + 1e-7 * p.C.row(0).reverse();
  expect_refused(p, 0.0, Status::kNotPositiveDefinite);
}

// Finite inputs whose update overflows: S = 1e-300, L = 1e-150, L^-1 (z - C x) = 1e450.
TEST(FixedSolution, OverflowIsNotFinite) {
  Problem p = random_problem(6, 2, 20);
  p.prior.P = 1e-300 * Eigen::MatrixXd::Identity(6, 6);
  p.C = Eigen::MatrixXd::Identity(2, 6);
  p.z.setConstant(1e300);
  expect_refused(p, 0.0, Status::kNotFinite);
}

TEST(FixedSolution, NanInTheFixIsNotFinite) {
  Problem p = random_problem(6, 3, 13);
  p.z(1) = std::numeric_limits<double>::quiet_NaN();
  expect_refused(p, 0.0, Status::kNotFinite);
}

TEST(FixedSolution, NanInTheCovarianceIsNotFinite) {
  Problem p = random_problem(6, 3, 14);
  p.prior.P(2, 4) = std::numeric_limits<double>::quiet_NaN();
  expect_refused(p, 0.0, Status::kNotFinite);
}

TEST(FixedSolution, NanVarianceIsNotFinite) {
  expect_refused(random_problem(6, 3, 15), std::numeric_limits<double>::quiet_NaN(), Status::kNotFinite);
}

TEST(FixedSolution, NegativeVarianceIsRefused) {
  expect_refused(random_problem(6, 3, 16), -1e-3, Status::kNegativeVariance);
}

TEST(FixedSolution, SizeMismatchIsRefused) {
  Problem p = random_problem(6, 3, 17);
  p.z = p.z.head(2).eval();
  expect_refused(p, 0.0, Status::kSizeMismatch);
}

TEST(FixedSolution, BeyondCapacityIsRefused) {
  expect_refused(random_problem(21, 3, 18), 0.0, Status::kOutOfCapacity);  // capacity 20 states
}

TEST(FixedSolution, NoConstraintIsANoOp) {
  const Problem p = random_problem(6, 0, 19);
  auto update = FixedSolutionUpdate::create(6).value();
  Gaussian state = p.prior;
  EXPECT_EQ(update.apply(state.x, state.P, p.C, p.z), Status::kOk);
  EXPECT_EQ(state.P, p.prior.P);
}

// --- Fixed constraints and end to end ---------------------------------------------------------
// A simulated SD filter, state [baseline (3) m, SD ambiguities of L1 (8 satellites) cycles]:
// covariance from one epoch of SD phase and code with a 5 cm baseline prior
// (support/dd_geometry.hpp), true SD ambiguities = integers + a common receiver phase offset
// (0.37 cycles, cancels in the DDs), float state = truth + N(0, P).
struct SdFilter {
  static constexpr int kSatellites = 8;
  static constexpr Index kStates = 3 + kSatellites;
  Eigen::VectorXd x_true;
  Eigen::VectorXd x_float;
  Eigen::MatrixXd P;
  int reference = 0;  // satellite index of the reference (the highest)
};

SdFilter simulate_sd_filter(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  test::DdGeometryOptions o;
  o.satellites = SdFilter::kSatellites;
  o.frequencies = 1;
  const test::LinesOfSight sight = test::draw_lines_of_sight(o.satellites, rng);
  SdFilter f;
  f.reference = sight.reference;
  f.P = test::sd_filter_covariance(sight, o, 0.05);
  f.x_true.resize(SdFilter::kStates);
  f.x_true.head(3) << 12.3, -4.5, 2.1;  // baseline [m]
  f.x_true.tail(SdFilter::kSatellites) = test::random_integers(SdFilter::kSatellites, 1e6, rng).array() + 0.37;
  const Eigen::MatrixXd chol = f.P.llt().matrixL();
  f.x_float = test::float_ambiguities(f.x_true, chol, rng);  // truth + N(0, P)
  return f;
}

DoubleDifferenceAmbiguities dd_of(const SdFilter& f) {
  auto dd = DoubleDifferenceAmbiguities::create(SdFilter::kStates).value();
  EXPECT_TRUE(dd.reset(SdFilter::kStates));
  std::vector<Index> others;
  for (int i = 0; i < SdFilter::kSatellites; ++i) {
    if (i != f.reference) others.push_back(3 + i);
  }
  EXPECT_TRUE(dd.add_group(3 + f.reference, others));
  EXPECT_TRUE(dd.evaluate(f.x_float, f.P));
  return dd;
}

struct Fixed {
  AmbiguityFix fix;
  Index k = 0;
  Eigen::MatrixXd C;
  Eigen::VectorXd z;
  Gaussian state;
  Status status = Status::kSizeMismatch;
};

Fixed fix_filter(const SdFilter& f, IntegerLeastSquares& ils, const DoubleDifferenceAmbiguities& dd,
                 const AcceptanceSettings& settings = {}) {
  Fixed out;
  out.fix = resolve_ambiguities(ils, dd.a(), dd.Q(), settings);
  out.C = Eigen::MatrixXd::Zero(kMaxAmbiguities, SdFilter::kStates);
  out.z = Eigen::VectorXd::Zero(kMaxAmbiguities);
  out.k = fixed_constraints(out.fix, ils, dd, out.C, out.z);
  out.state = {f.x_float, f.P};
  auto update = FixedSolutionUpdate::create(SdFilter::kStates).value();
  out.status = update.apply(out.state.x, out.state.P, out.C.topRows(out.k), out.z.head(out.k));
  return out;
}

constexpr std::uint64_t kSeeds[] = {21, 22, 23, 24, 25};

TEST(FixedSolutionEndToEnd, FullFixOfTheTrueIntegers) {
  for (const std::uint64_t seed : kSeeds) {
    const SdFilter f = simulate_sd_filter(seed);
    const auto dd = dd_of(f);
    auto ils = IntegerLeastSquares::create().value();
    const Fixed fixed = fix_filter(f, ils, dd);
    ASSERT_EQ(fixed.fix.outcome, FixOutcome::kFixed) << seed;
    EXPECT_EQ(ils.solution().a.col(0), (dd.G() * f.x_true).array().round().matrix()) << seed;  // the true DDs
  }
}

// C x_true = Z_k' G x_true = Z_k' a_true: with the right integers, z (integer parts included) is
// exactly the true value of the fixed combinations (the check of the ILS's integer-part removal).
TEST(FixedSolutionEndToEnd, FixedConstraintsHoldForTheTruth) {
  for (const std::uint64_t seed : kSeeds) {
    const SdFilter f = simulate_sd_filter(seed);
    const auto dd = dd_of(f);
    auto ils = IntegerLeastSquares::create().value();
    const Fixed fixed = fix_filter(f, ils, dd);
    ASSERT_EQ(fixed.k, SdFilter::kSatellites - 1) << seed;
    EXPECT_LT(max_abs(fixed.C.topRows(fixed.k) * f.x_true - fixed.z.head(fixed.k)), 1e-6) << seed;
  }
}

TEST(FixedSolutionEndToEnd, FixedConstraintsAreTheDecorrelatedFloats) {
  const SdFilter f = simulate_sd_filter(21);
  const auto dd = dd_of(f);
  auto ils = IntegerLeastSquares::create().value();
  const Fixed fixed = fix_filter(f, ils, dd);
  ASSERT_GT(fixed.k, 0);
  const Index n = dd.size();
  // z_hat = Z' a, integer parts included (DecorrelatedAmbiguities); C x_float is its trailing k.
  EXPECT_LT(max_abs(fixed.C.topRows(fixed.k) * f.x_float - ils.decorrelated().z_hat.segment(n - fixed.k, fixed.k)), 1e-6);
}

TEST(FixedSolutionEndToEnd, FixedBaselineIsCloserToTruthThanFloat) {
  for (const std::uint64_t seed : kSeeds) {
    const SdFilter f = simulate_sd_filter(seed);
    const auto dd = dd_of(f);
    auto ils = IntegerLeastSquares::create().value();
    const Fixed fixed = fix_filter(f, ils, dd);
    ASSERT_EQ(fixed.status, Status::kOk) << seed;
    const double float_error = (f.x_float.head(3) - f.x_true.head(3)).norm();
    const double fixed_error = (fixed.state.x.head(3) - f.x_true.head(3)).norm();
    EXPECT_LT(fixed_error, float_error) << seed;
  }
}

// What the exact integers imply: the baseline conditioned on G x = a_true, computed independently
// (KKT) from the same float state.
TEST(FixedSolutionEndToEnd, FixedStateIsTheConditionalOnTheTrueIntegers) {
  for (const std::uint64_t seed : kSeeds) {
    const SdFilter f = simulate_sd_filter(seed);
    const auto dd = dd_of(f);
    auto ils = IntegerLeastSquares::create().value();
    const Fixed fixed = fix_filter(f, ils, dd);
    const Eigen::MatrixXd G = dd.G();
    const Gaussian expected = constrained_least_squares({f.x_float, f.P}, G, (G * f.x_true).array().round().matrix());
    EXPECT_LT(max_abs(fixed.state.x.head(3) - expected.x.head(3)), 1e-9) << seed;  // [m]
  }
}

TEST(FixedSolutionEndToEnd, FixedBaselineErrorWithinItsCovariance) {
  for (const std::uint64_t seed : kSeeds) {
    const SdFilter f = simulate_sd_filter(seed);
    const auto dd = dd_of(f);
    auto ils = IntegerLeastSquares::create().value();
    const Fixed fixed = fix_filter(f, ils, dd);
    for (Index i = 0; i < 3; ++i) {
      // 5 sigma of the fixed covariance (mm level): a Gaussian error beyond it has p < 6e-7.
      EXPECT_LT(std::abs(fixed.state.x(i) - f.x_true(i)), 5.0 * std::sqrt(fixed.state.P(i, i))) << seed << " " << i;
    }
  }
}

TEST(FixedSolutionEndToEnd, PartialFixConstraintsHoldForTheTruth) {
  const SdFilter f = simulate_sd_filter(21);
  const auto dd = dd_of(f);
  auto ils = IntegerLeastSquares::create().value();
  const Eigen::Index n = dd.size();
  ASSERT_EQ(ils.decorrelate(dd.a(), dd.Q()), IlsStatus::kOk);
  ASSERT_EQ(ils.search(n - 3), IlsStatus::kOk);  // the 4 best-determined combinations
  AmbiguityFix partial;
  partial.outcome = FixOutcome::kPartial;
  partial.fixed = n - 3;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, SdFilter::kStates);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  ASSERT_EQ(fixed_constraints(partial, ils, dd, C, z), n - 3);
  EXPECT_LT(max_abs(C.topRows(n - 3) * f.x_true - z.head(n - 3)), 1e-6);
}

// The contract, whatever the count says: a float outcome never yields constraints.
TEST(FixedSolutionEndToEnd, FloatOutcomeGivesNoConstraint) {
  const SdFilter f = simulate_sd_filter(21);
  const auto dd = dd_of(f);
  auto ils = IntegerLeastSquares::create().value();
  AmbiguityFix fix = resolve_ambiguities(ils, dd.a(), dd.Q(), AcceptanceSettings{});
  ASSERT_EQ(fix.outcome, FixOutcome::kFixed);
  fix.outcome = FixOutcome::kFloat;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(kMaxAmbiguities, SdFilter::kStates);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(kMaxAmbiguities);
  EXPECT_EQ(fixed_constraints(fix, ils, dd, C, z), 0);
}

TEST(FixedSolutionEndToEnd, RatioRefusalGivesNoConstraint) {
  const SdFilter f = simulate_sd_filter(21);
  const auto dd = dd_of(f);
  auto ils = IntegerLeastSquares::create().value();
  AcceptanceSettings impossible;
  impossible.min_ratio = 1e12;  // the ratio test refuses
  EXPECT_EQ(fix_filter(f, ils, dd, impossible).k, 0);
}

TEST(FixedSolutionEndToEnd, MismatchedConstraintStorageGivesNoConstraint) {
  const SdFilter f = simulate_sd_filter(21);
  const auto dd = dd_of(f);
  auto ils = IntegerLeastSquares::create().value();
  const AmbiguityFix fix = resolve_ambiguities(ils, dd.a(), dd.Q(), AcceptanceSettings{});
  ASSERT_EQ(fix.outcome, FixOutcome::kFixed);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(kMaxAmbiguities, SdFilter::kStates + 1);  // one column too many
  Eigen::VectorXd z = Eigen::VectorXd::Zero(kMaxAmbiguities);
  EXPECT_EQ(fixed_constraints(fix, ils, dd, C, z), 0);
}

}  // namespace
}  // namespace visors::nav
