// Sequential scalar Joseph update (docs/algorithms/cdgps-filter.md#sequential-scalar-updates)
// against textbook dense formulas evaluated independently on dynamic Eigen matrices: the Joseph
// form
// (I - K H) P (I - K H)' + K R K' formed with the explicit n x n I - K H, the short form
// (I - K H) P, and the batch update K = P H' (H P H' + R)^-1; the gate; refused input.
#include "visors/nav/scalar_update.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "support/random_orthogonal.hpp"

namespace visors::nav {
namespace {

using Eigen::MatrixXd;
using Eigen::RowVectorXd;
using Eigen::VectorXd;

struct Filter {
  NavVector x;
  NavMatrix P;
};

// Random SPD P = U diag(ev) U' (Haar U), eigenvalues log-uniform in [lo, hi]; x ~ N(0, 1).
Filter random_filter(std::mt19937_64& rng, double lo = 1e-2, double hi = 1e2) {
  std::uniform_real_distribution<double> log_ev(std::log(lo), std::log(hi));
  std::normal_distribution<double> gauss;
  VectorXd ev(kNavStates);
  for (int i = 0; i < kNavStates; ++i) ev(i) = std::exp(log_ev(rng));
  Filter f;
  f.P = test::spd_with_eigenvalues(test::haar_orthogonal(kNavStates, rng), ev);
  for (int i = 0; i < kNavStates; ++i) f.x(i) = gauss(rng);
  return f;
}

NavRow random_row(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  NavRow h;
  for (int i = 0; i < kNavStates; ++i) h(i) = gauss(rng);
  return h;
}

double max_abs(const MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }
double relative_difference(const MatrixXd& a, const MatrixXd& reference) {
  return max_abs(a - reference) / max_abs(reference);
}

// Textbook Joseph form with the explicit I - K H (Bucy & Joseph 1968).
MatrixXd dense_joseph(const MatrixXd& P, const RowVectorXd& h, const VectorXd& k, double r) {
  const MatrixXd A = MatrixXd::Identity(P.rows(), P.cols()) - k * h;
  return A * P * A.transpose() + k * r * k.transpose();
}

// Textbook short form (I - K H) P.
MatrixXd dense_short_form(const MatrixXd& P, const RowVectorXd& h, const VectorXd& k) {
  return (MatrixXd::Identity(P.rows(), P.cols()) - k * h) * P;
}

VectorXd optimal_gain(const MatrixXd& P, const RowVectorXd& h, double r) {
  return P * h.transpose() / ((h * P * h.transpose()).value() + r);
}

bool bit_identical(const Filter& a, const Filter& b) {
  return std::memcmp(a.x.data(), b.x.data(), sizeof(double) * kNavStates) == 0 &&
         std::memcmp(a.P.data(), b.P.data(), sizeof(double) * kNavStates * kNavStates) == 0;
}

bool positive_definite(const MatrixXd& P) { return Eigen::LLT<MatrixXd>(P).info() == Eigen::Success; }

constexpr double kWideGate = 1e3;  // sigmas: no gating intended

TEST(ScalarUpdate, AcceptsAnInnovationWithinTheGate) {
  std::mt19937_64 rng(1);
  Filter f = random_filter(rng);
  ScalarUpdateWorkspace ws;
  EXPECT_EQ(scalar_update(f.x, f.P, random_row(rng), 0.3, 0.5, 5.0, ws).status, ScalarUpdateStatus::kAccepted);
}

TEST(ScalarUpdate, JosephRankOneEqualsDenseJosephWithOptimalGain) {
  std::mt19937_64 rng(2);
  const Filter prior = random_filter(rng);
  const NavRow h = random_row(rng);
  const double r = 0.5;
  Filter f = prior;
  ScalarUpdateWorkspace ws;
  (void)scalar_update(f.x, f.P, h, 0.3, r, kWideGate, ws);
  const MatrixXd expected = dense_joseph(prior.P, h, optimal_gain(prior.P, h, r), r);
  EXPECT_LT(relative_difference(f.P, expected), 1e-13);  // round-off: ~100 eps
}

// Consider states (Schmidt): a zero in the gain mask holds that state's estimate while the
// covariance is the Joseph form of the masked gain (Bucy & Joseph; Zanetti & D'Souza 2012).
TEST(ScalarUpdate, ConsiderStateEstimateIsHeld) {
  std::mt19937_64 rng(41);
  Filter f = random_filter(rng);
  const double held = f.x(12);
  ScalarUpdateWorkspace ws;
  ws.gain_mask(12) = 0.0;
  (void)scalar_update(f.x, f.P, random_row(rng), 0.3, 0.5, kWideGate, ws);
  EXPECT_EQ(f.x(12), held);
}

TEST(ScalarUpdate, ConsiderCovarianceEqualsDenseJosephWithMaskedGain) {
  std::mt19937_64 rng(42);
  const Filter prior = random_filter(rng);
  const NavRow h = random_row(rng);
  const double r = 0.5;
  Filter f = prior;
  ScalarUpdateWorkspace ws;
  ws.gain_mask.segment<3>(10).setZero();
  (void)scalar_update(f.x, f.P, h, 0.3, r, kWideGate, ws);
  const VectorXd k = optimal_gain(prior.P, h, r).cwiseProduct(ws.gain_mask);
  EXPECT_LT(relative_difference(f.P, dense_joseph(prior.P, h, k, r)), 1e-13);
}

// A gate variance of its own (sdcp_correlation_inflation): the update weighs by the inflated
// variance, the gate judges against the per-epoch one.
TEST(ScalarUpdate, GateVarianceOfItsOwnRejectsWhatTheInflatedVarianceWouldPass) {
  std::mt19937_64 rng(43);
  Filter f = random_filter(rng, 1e-8, 1e-6);  // a converged filter: h P h' << r
  const NavRow h = NavRow::Unit(0);
  ScalarUpdateWorkspace ws;
  EXPECT_EQ(scalar_update_lower(f.x, f.P, h, 0.02, 100.0 * 1e-5, 1e-5, 5.0, ws).status, ScalarUpdateStatus::kRejected);
}

TEST(ScalarUpdate, GateVarianceOfItsOwnLeavesTheUpdateOnTheWeightVariance) {
  std::mt19937_64 rng(44);
  const Filter prior = random_filter(rng);
  const NavRow h = random_row(rng);
  Filter f = prior;
  ScalarUpdateWorkspace ws;
  (void)scalar_update_lower(f.x, f.P, h, 0.3, 50.0, 0.5, kWideGate, ws);
  mirror_lower(f.P);
  EXPECT_LT(relative_difference(f.P, dense_joseph(prior.P, h, optimal_gain(prior.P, h, 50.0), 50.0)), 1e-13);
}

TEST(ScalarUpdate, JosephEqualsShortFormWithOptimalGain) {
  std::mt19937_64 rng(3);
  const Filter prior = random_filter(rng);
  const NavRow h = random_row(rng);
  const double r = 0.5;
  Filter f = prior;
  ScalarUpdateWorkspace ws;
  (void)scalar_update(f.x, f.P, h, 0.3, r, kWideGate, ws);
  // With the optimal K the Joseph and short forms agree to round-off.
  EXPECT_LT(relative_difference(f.P, dense_short_form(prior.P, h, optimal_gain(prior.P, h, r))), 1e-13);
}

TEST(ScalarUpdate, StateMovesByGainTimesInnovation) {
  std::mt19937_64 rng(4);
  const Filter prior = random_filter(rng);
  const NavRow h = random_row(rng);
  Filter f = prior;
  ScalarUpdateWorkspace ws;
  (void)scalar_update(f.x, f.P, h, 0.3, 0.5, kWideGate, ws);
  const VectorXd expected = prior.x + optimal_gain(prior.P, h, 0.5) * 0.3;  // x+ = x + K nu
  EXPECT_LT(relative_difference(f.x, expected), 1e-14);
}

TEST(ScalarUpdate, CovarianceComesOutExactlySymmetric) {
  std::mt19937_64 rng(5);
  Filter f = random_filter(rng);
  ScalarUpdateWorkspace ws;
  (void)scalar_update(f.x, f.P, random_row(rng), 0.3, 0.5, kWideGate, ws);
  EXPECT_EQ(MatrixXd(f.P), MatrixXd(f.P.transpose()));
}

TEST(ScalarUpdate, ReportsInnovationVarianceAndNis) {
  std::mt19937_64 rng(6);
  Filter f = random_filter(rng);
  const NavRow h = random_row(rng);
  const double s = (h * f.P * h.transpose()).value() + 0.5;  // s = h P h' + r
  ScalarUpdateWorkspace ws;
  const ScalarUpdateResult result = scalar_update(f.x, f.P, h, 0.3, 0.5, kWideGate, ws);
  EXPECT_NEAR(result.innovation_variance, s, 1e-13 * s);
  EXPECT_NEAR(result.normalised_innovation_squared, 0.09 / s, 1e-13 * 0.09 / s);  // nu^2 / s
}

// A precise measurement of a poorly known combination (r = 1e-4 h P h'; an SDCP of (2.8 mm)^2
// against a metre-level prior is more extreme still). Gain 1 % high: the short form
// P - 1.01 u u' / s has h P+ h' = c (1 - 1.01 c / (c + r)) < 0, indefinite; the Joseph form is
// a congruence of P plus r k k', positive definite for any gain.
struct PerturbedGainCase {
  Filter prior;
  NavRow h;
  double r = 0.0;
  NavVector k;  // 1.01 x the optimal gain
};

PerturbedGainCase perturbed_gain_case() {
  std::mt19937_64 rng(7);
  PerturbedGainCase c;
  c.prior = random_filter(rng, 1.0, 1e4);
  c.h = random_row(rng);
  c.r = 1e-4 * (c.h * c.prior.P * c.h.transpose()).value();
  c.k = 1.01 * optimal_gain(c.prior.P, c.h, c.r);
  return c;
}

TEST(ScalarUpdate, JosephStaysPositiveDefiniteWithGainOnePercentHigh) {
  const PerturbedGainCase c = perturbed_gain_case();
  NavMatrix P = c.prior.P;
  NavVector work;
  ASSERT_TRUE(joseph_update(P, c.h, c.k, c.r, work));
  EXPECT_TRUE(positive_definite(P));  // Cholesky succeeds
}

TEST(ScalarUpdate, ShortFormLosesDefinitenessWithGainOnePercentHigh) {
  const PerturbedGainCase c = perturbed_gain_case();
  // What the Joseph form protects against (the control of the test above).
  EXPECT_FALSE(positive_definite(dense_short_form(c.prior.P, c.h, c.k)));
}

TEST(ScalarUpdate, JosephRankOneEqualsDenseJosephWithPerturbedGain) {
  const PerturbedGainCase c = perturbed_gain_case();
  NavMatrix P = c.prior.P;
  NavVector work;
  ASSERT_TRUE(joseph_update(P, c.h, c.k, c.r, work));
  EXPECT_LT(relative_difference(P, dense_joseph(c.prior.P, c.h, c.k, c.r)), 1e-12);
}

TEST(ScalarUpdate, JosephUpdateRefusesNegativeVarianceLeavingPUntouched) {
  const PerturbedGainCase c = perturbed_gain_case();
  NavMatrix P = c.prior.P;
  NavVector work;
  EXPECT_FALSE(joseph_update(P, c.h, c.k, -1.0, work));
  EXPECT_EQ(std::memcmp(P.data(), c.prior.P.data(), sizeof(double) * kNavStates * kNavStates), 0);
}

// Gate at 5 sigma (|nu| <= k sqrt(H P H' + R), k = 5 the filter's default gate_sigmas).
struct GateCase {
  Filter prior;
  NavRow h;
  double r = 0.04;
  double sigma = 0.0;  // sqrt(h P h' + r), dense
};

GateCase gate_case() {
  std::mt19937_64 rng(8);
  GateCase c;
  c.prior = random_filter(rng);
  c.h = random_row(rng);
  c.sigma = std::sqrt((c.h * c.prior.P * c.h.transpose()).value() + c.r);
  return c;
}

TEST(ScalarUpdate, GateRejectsBeyondFiveSigma) {
  const GateCase c = gate_case();
  Filter f = c.prior;
  ScalarUpdateWorkspace ws;
  EXPECT_EQ(scalar_update(f.x, f.P, c.h, 5.01 * c.sigma, c.r, 5.0, ws).status, ScalarUpdateStatus::kRejected);
}

TEST(ScalarUpdate, GateRejectionLeavesStateAndCovarianceBitIdentical) {
  const GateCase c = gate_case();
  Filter f = c.prior;
  ScalarUpdateWorkspace ws;
  (void)scalar_update(f.x, f.P, c.h, -5.01 * c.sigma, c.r, 5.0, ws);
  EXPECT_TRUE(bit_identical(f, c.prior));
}

TEST(ScalarUpdate, GateRejectionReportsNormalisedInnovation) {
  const GateCase c = gate_case();
  Filter f = c.prior;
  ScalarUpdateWorkspace ws;
  EXPECT_NEAR(scalar_update(f.x, f.P, c.h, 5.01 * c.sigma, c.r, 5.0, ws).normalised_innovation, 5.01, 1e-12);
}

TEST(ScalarUpdate, GateAcceptsJustInsideFiveSigma) {
  const GateCase c = gate_case();
  Filter f = c.prior;
  ScalarUpdateWorkspace ws;
  EXPECT_EQ(scalar_update(f.x, f.P, c.h, -4.99 * c.sigma, c.r, 5.0, ws).status, ScalarUpdateStatus::kAccepted);
}

TEST(ScalarUpdate, InvalidInputsAreRefusedLeavingStateBitIdentical) {
  std::mt19937_64 rng(9);
  const Filter prior = random_filter(rng);
  const NavRow h = random_row(rng);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    const char* name;
    double innovation, variance, gate;
    int bad_h, bad_x, bad_P;  // index poisoned with NaN, -1 none
  };
  const Case cases[] = {
      {"nan innovation", nan, 0.5, 5.0, -1, -1, -1},  {"inf innovation", inf, 0.5, 5.0, -1, -1, -1},
      {"nan variance", 0.3, nan, 5.0, -1, -1, -1},    {"inf variance", 0.3, inf, 5.0, -1, -1, -1},
      {"zero variance", 0.3, 0.0, 5.0, -1, -1, -1},   {"negative variance", 0.3, -0.5, 5.0, -1, -1, -1},
      {"zero gate", 0.3, 0.5, 0.0, -1, -1, -1},       {"nan gate", 0.3, 0.5, nan, -1, -1, -1},
      {"nan in h", 0.3, 0.5, 5.0, 40, -1, -1},        {"nan in x", 0.3, 0.5, 5.0, -1, 12, -1},
      {"nan in P (off-diagonal)", 0.3, 0.5, 5.0, -1, -1, 5 * kNavStates + 60},
  };
  for (const Case& c : cases) {
    Filter f = prior;
    NavRow row = h;
    if (c.bad_h >= 0) row(c.bad_h) = nan;
    if (c.bad_x >= 0) f.x(c.bad_x) = nan;
    if (c.bad_P >= 0) f.P.data()[c.bad_P] = nan;
    const Filter poisoned = f;
    ScalarUpdateWorkspace ws;
    EXPECT_EQ(scalar_update(f.x, f.P, row, c.innovation, c.variance, c.gate, ws).status, ScalarUpdateStatus::kInvalid)
        << c.name;
    EXPECT_TRUE(bit_identical(f, poisoned)) << c.name;
  }
}

// s = h P h' + r <= 0: P not positive semidefinite along h (here P = -I).
TEST(ScalarUpdate, NonPositiveInnovationVarianceIsRefused) {
  Filter f;
  f.x.setZero();
  f.P = -NavMatrix::Identity();
  NavRow h = NavRow::Zero();
  h(3) = 1.0;
  ScalarUpdateWorkspace ws;
  EXPECT_EQ(scalar_update(f.x, f.P, h, 0.1, 0.5, 5.0, ws).status, ScalarUpdateStatus::kInvalid);
}

// m = 12 random scalars with diagonal R (sparse rows when asked, like the GPS scalars', which
// exercise both halves of P h' on the lower triangle) and the textbook batch update of the prior:
// K = P H' (H P H' + R)^-1 with the explicit inverse of the m x m S, x+ = x + K (z - H x),
// P+ = (I - K H) P.
struct BatchProblem {
  Filter prior, batch;
  MatrixXd H;
  VectorXd r, z;
};

BatchProblem batch_problem(std::uint64_t seed, bool sparse) {
  std::mt19937_64 rng(seed);
  BatchProblem b;
  b.prior = random_filter(rng);
  constexpr int m = 12;
  b.H.resize(m, kNavStates);
  b.r.resize(m);
  b.z.resize(m);
  std::uniform_real_distribution<double> variance(0.1, 1.0);
  std::normal_distribution<double> gauss;
  for (int i = 0; i < m; ++i) {
    b.H.row(i) = random_row(rng);
    for (int j = 0; sparse && j < kNavStates; ++j) {
      if (gauss(rng) > 0.5) b.H(i, j) = 0.0;
    }
    b.r(i) = variance(rng);
    b.z(i) = (b.H.row(i) * b.prior.x).value() + std::sqrt(b.r(i)) * gauss(rng);
  }
  const MatrixXd& P = b.prior.P;
  const MatrixXd K = P * b.H.transpose() * (b.H * P * b.H.transpose() + MatrixXd(b.r.asDiagonal())).inverse();
  b.batch.x = b.prior.x + K * (b.z - b.H * b.prior.x);
  b.batch.P = (MatrixXd::Identity(kNavStates, kNavStates) - K * b.H) * P;
  return b;
}

// The m scalars one after another (each innovation against the state updated by the previous
// ones) equal the batch update.
TEST(ScalarUpdate, SequentialScalarsEqualOneBatchUpdate) {
  const BatchProblem b = batch_problem(10, false);
  Filter f = b.prior;
  ScalarUpdateWorkspace ws;
  for (int i = 0; i < b.H.rows(); ++i) {
    const NavRow h = b.H.row(i);
    ASSERT_EQ(scalar_update(f.x, f.P, h, b.z(i) - (h * f.x).value(), b.r(i), kWideGate, ws).status,
              ScalarUpdateStatus::kAccepted);
  }
  EXPECT_LT(relative_difference(f.x, b.batch.x), 1e-10);
  EXPECT_LT(relative_difference(f.P, b.batch.P), 1e-10);
}

// A run of scalar_update_lower with one mirror_lower at the end equals the batch update too, with
// the strict upper triangle of P poisoned with NaN before the run (so a read of it anywhere, in
// P h' or the Joseph change, would put NaN into x or the lower triangle).
struct LowerRun {
  Filter batch;
  Filter run;
};

LowerRun lower_run_against_batch(std::uint64_t seed) {
  const BatchProblem b = batch_problem(seed, true);
  LowerRun out{b.batch, b.prior};
  out.run.P.triangularView<Eigen::StrictlyUpper>().setConstant(std::numeric_limits<double>::quiet_NaN());
  ScalarUpdateWorkspace ws;
  for (int i = 0; i < b.H.rows(); ++i) {
    const NavRow h = b.H.row(i);
    (void)scalar_update_lower(out.run.x, out.run.P, h, b.z(i) - (h * out.run.x).value(), b.r(i), kWideGate, ws);
  }
  mirror_lower(out.run.P);
  return out;
}

TEST(ScalarUpdate, LowerTriangleRunGivesTheBatchState) {
  const LowerRun r = lower_run_against_batch(11);
  EXPECT_LT(relative_difference(r.run.x, r.batch.x), 1e-10);
}

TEST(ScalarUpdate, LowerTriangleRunThenMirrorGivesTheBatchCovariance) {
  const LowerRun r = lower_run_against_batch(11);
  ASSERT_TRUE(r.run.P.allFinite());
  EXPECT_LT(relative_difference(r.run.P, r.batch.P), 1e-10);
}

TEST(ScalarUpdate, MirrorLowerMakesPExactlySymmetric) {
  const LowerRun r = lower_run_against_batch(12);
  EXPECT_EQ(r.run.P, r.run.P.transpose());
}

}  // namespace
}  // namespace visors::nav
