// Transition and process noise of the Gauss-Markov empirical-acceleration chain
// (nav/gauss_markov.hpp; docs/algorithms/cdgps-filter.md#empirical-accelerations) against:
// - Van Loan's method (IEEE TAC 23(3), 1978) computed here with Eigen's independent matrix
//   exponential (unsupported/Eigen/MatrixFunctions, Pade approximant with scaling and squaring);
// - the same method in 200-digit decimal arithmetic (tests/nav/gauss_markov_reference.py, its
//   output pasted below), because the double-precision Van Loan degrades where the code must not:
//   the blocks of the 6x6 exponential span e^(+-dt/tau) and Q = Phi E12 cancels them (measured:
//   Q within 4.4e-15 of the exact values for dt/tau <= 2, 2.9e-13 at 5, 6.4e-11 at 10, useless at
//   100); it stays accurate for tiny dt/tau (2.4e-15 at 1e-8, dt = 10 s);
// - the closed forms evaluated in 40-digit arithmetic at tau = 600 s, sigma = 5e-8 m/s^2, dt = 10 s
//   (docs/algorithms/cdgps-filter.md#worked-example-gauss-markov-noise);
// - the integrated random walk (tau -> infinity: the white-noise jerk model, q dt^5 / 20 ... q dt,
//   Bar-Shalom, Li & Kirubarajan 2001) and the stationary variance sigma^2 (tau -> 0);
// - the semigroup property of the exact discretisation (two steps of dt = one step of 2 dt).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <unsupported/Eigen/MatrixFunctions>

#include "visors/nav/gauss_markov.hpp"

namespace visors::nav {
namespace {

constexpr double kSigma = 5e-8;  // [m/s^2], a LEO reduced-dynamic value (the filter's default: 1e-7)
constexpr double kDt = 10.0;     // [s]

/// Largest |a_ij - b_ij| / |b_ij| (equal elements, zeros included, count as 0; NaN as infinite).
double max_relative_error(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  double worst = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (a(i, j) == b(i, j)) continue;
      const double e = std::abs(a(i, j) - b(i, j)) / std::abs(b(i, j));
      if (std::isnan(e)) return std::numeric_limits<double>::infinity();
      worst = std::max(worst, e);
    }
  }
  return worst;
}

/// Van Loan: E = expm([[-A, G q G'], [0, A']] dt), Phi = E22', Q = Phi E12.
GaussMarkovChain van_loan(double dt, double tau, double sigma) {
  Eigen::Matrix3d a;
  a << 0.0, 1.0, 0.0,
       0.0, 0.0, 1.0,
       0.0, 0.0, -1.0 / tau;
  Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
  m.topLeftCorner<3, 3>() = -a * dt;
  m.bottomRightCorner<3, 3>() = a.transpose() * dt;
  m(2, 5) = 2.0 * sigma * sigma / tau * dt;  // G q G' dt, G = e3
  const Eigen::Matrix<double, 6, 6> e = m.exp();
  GaussMarkovChain chain;
  chain.transition = e.bottomRightCorner<3, 3>().transpose();
  chain.noise = chain.transition * e.topRightCorner<3, 3>();
  return chain;
}

TEST(GaussMarkov, NoiseMatchesVanLoanWithEigenExpm) {
  for (double x : {1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0}) {
    SCOPED_TRACE(x);
    const GaussMarkovChain ref = van_loan(kDt, kDt / x, kSigma);
    EXPECT_LE(max_relative_error(gauss_markov_chain(kDt, kDt / x, kSigma).noise, ref.noise), 1e-9);
  }
}

TEST(GaussMarkov, TransitionMatchesVanLoanWithEigenExpm) {
  for (double x : {1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0}) {
    SCOPED_TRACE(x);
    const GaussMarkovChain ref = van_loan(kDt, kDt / x, kSigma);
    // Upper triangles: the structural zeros below come out of the Pade approximant as round-off
    // (~1e-15 beside elements of 50); the exact-arithmetic test below checks them.
    const Eigen::Matrix3d ref_upper = ref.transition.triangularView<Eigen::Upper>();
    const Eigen::Matrix3d upper = gauss_markov_chain(kDt, kDt / x, kSigma).transition.triangularView<Eigen::Upper>();
    EXPECT_LE(max_relative_error(upper, ref_upper), 1e-9);
  }
}

// Van Loan in 200-digit decimal arithmetic: output of
//   /usr/bin/python3 tests/nav/gauss_markov_reference.py
// (the inputs are the exact values of the doubles below; tau = dt / x evaluated in double).
struct ExactCase {
  double x, dt, tau, sigma, phi_ra, phi_va, phi_aa, q_rr, q_rv, q_ra, q_vv, q_va, q_aa;
};
// clang-format off
constexpr std::array<ExactCase, 12> kExact{{
{1e-8, 10.0, 1000000000.0, 5e-08, 49.999999833333334, 9.9999999499999994, 0.99999999000000006, 2.499999986111111e-20, 6.249999958333333e-21, 8.3333332499999996e-22, 1.6666666541666666e-21, 2.4999999749999997e-22, 4.9999999500000001e-23},
{1e-6, 10.0, 10000000.0, 5e-08, 49.999983333337497, 9.9999950000016664, 0.99999900000050002, 2.4999986111116068e-18, 6.2499958333350688e-19, 8.3333250000045828e-20, 1.6666654166672499e-19, 2.4999975000014581e-20, 4.9999950000033332e-21},
{1e-4, 10.0, 100000.0, 5e-08, 49.99833337499917, 9.99950001666625, 0.99990000499983334, 2.4998611160712892e-16, 6.249583350693888e-17, 8.3325000458315268e-18, 1.6665416724997915e-17, 2.4997500145827079e-18, 4.9995000333316659e-19},
{1e-3, 10.0, 10000.0, 5e-08, 49.983337499166808, 9.9950016662500829, 0.99900049983337502, 2.4986116070040008e-15, 6.2458350688890362e-16, 8.325004581528342e-17, 1.6654172497917279e-16, 2.4975014577085483e-17, 4.9950033316673325e-18},
{1e-2, 10.0, 1000.0, 5e-08, 49.833749168053572, 9.9501662508319466, 0.99004983374916811, 2.4861605757240806e-14, 6.2085063903611999e-15, 8.2504565334176917e-16, 1.6542247922801869e-15, 2.4751452104798764e-16, 4.950331673311174e-17},
{0.1, 10.0, 100.0, 5e-08, 48.374180359595734, 9.516258196404042, 0.90483741803595963, 2.3659357524468274e-13, 5.8501533136567434e-14, 7.5440828706556669e-15, 1.5472976646410848e-14, 2.2639792515156778e-15, 4.5317311730504531e-16},
{1, 10.0, 10.0, 5e-08, 36.787944117144235, 6.3212055882855767, 0.36787944117144233, 1.4953404686071171e-12, 3.3833820809153171e-13, 3.2226458605125664e-14, 8.4045620362289141e-14, 9.9894100223432e-15, 2.1616617919084681e-15},
{1.4, 10.0, 7.142857142857143, 5e-08, 32.989641017428902, 5.3814502575599539, 0.24659696394160649, 1.7413335110053042e-12, 3.8091074506058954e-13, 3.1724290604372946e-14, 9.2548187900664267e-14, 1.0136002406107232e-14, 2.347974843436955e-15},
{2, 10.0, 5.0, 5e-08, 28.383382080915318, 4.3233235838169364, 0.1353352832366127, 1.9255241071120274e-12, 4.0280818917561235e-13, 2.7521451760300937e-14, 9.518909337860728e-14, 9.3455634051938584e-15, 2.4542109027781645e-15},
{5, 10.0, 2.0, 5e-08, 16.026951787996342, 1.986524106001829, 0.006737946999085467, 1.7679411597368744e-12, 3.210789795184489e-13, 9.3257513007938271e-15, 7.0269063880665784e-14, 4.9328475296579571e-15, 2.4998865001755937e-15},
{10, 10.0, 1.0, 5e-08, 9.0000453999297623, 0.99995460007023751, 4.5399929762484854e-05, 1.2191621266685374e-12, 2.0250204300199218e-13, 2.4977299983589915e-15, 4.2500453994144736e-14, 2.4997730055040713e-15, 2.4999999948471156e-15},
{100, 10.0, 0.1, 5e-08, 0.9900000000000001, 0.10000000000000001, 3.7200759760208565e-44, 1.6171691666666667e-13, 2.4502499999999998e-14, 2.4999999999999999e-17, 4.9250000000000002e-15, 2.4999999999999997e-16, 2.4999999999999996e-15},
}};
// clang-format on

Eigen::Matrix3d exact_noise(const ExactCase& c) {
  Eigen::Matrix3d q;
  q << c.q_rr, c.q_rv, c.q_ra,
       c.q_rv, c.q_vv, c.q_va,
       c.q_ra, c.q_va, c.q_aa;
  return q;
}

Eigen::Matrix3d exact_transition(const ExactCase& c) {
  Eigen::Matrix3d phi;
  phi << 1.0, c.dt, c.phi_ra,
         0.0, 1.0, c.phi_va,
         0.0, 0.0, c.phi_aa;
  return phi;
}

// Relative 1e-13: the requirement is ~1e-12 for every dt / tau in [1e-8, 100]; the implementation
// is designed for a few 1e-15 (header). The one input-conditioning limit: at x = 100, e^-x has a
// relative condition number of 100 in x, and x = dt / tau is rounded (Phi_aa ~ 1e-14).
TEST(GaussMarkov, NoiseMatchesExactArithmeticVanLoan) {
  for (const ExactCase& c : kExact) {
    SCOPED_TRACE(c.x);
    ASSERT_EQ(c.dt / c.x, c.tau);  // the script's tau is the double the test would form
    EXPECT_LE(max_relative_error(gauss_markov_chain(c.dt, c.tau, c.sigma).noise, exact_noise(c)), 1e-13);
  }
}

TEST(GaussMarkov, TransitionMatchesExactArithmeticVanLoan) {
  for (const ExactCase& c : kExact) {
    SCOPED_TRACE(c.x);
    EXPECT_LE(max_relative_error(gauss_markov_chain(c.dt, c.tau, c.sigma).transition, exact_transition(c)), 1e-13);
  }
}

// The worked example of docs/algorithms/cdgps-filter.md#worked-example-gauss-markov-noise (values
// printed to 8 significant digits): each must round to them, i.e. lie within half a unit of the
// 8th digit.
class GaussMarkovWorkedExample : public ::testing::Test {
 protected:
  const Eigen::Matrix3d q_ = gauss_markov_chain(10.0, 600.0, 5e-8).noise;
};

TEST_F(GaussMarkovWorkedExample, Qrr) { EXPECT_NEAR(q_(0, 0), 4.12831500e-14, 0.5e-8 * 1e-14); }
TEST_F(GaussMarkovWorkedExample, Qrv) { EXPECT_NEAR(q_(0, 1), 1.03017254e-14, 0.5e-8 * 1e-14); }
TEST_F(GaussMarkovWorkedExample, Qra) { EXPECT_NEAR(q_(0, 2), 1.36595155e-15, 0.5e-8 * 1e-15); }
TEST_F(GaussMarkovWorkedExample, Qvv) { EXPECT_NEAR(q_(1, 1), 2.74332402e-15, 0.5e-8 * 1e-15); }
TEST_F(GaussMarkovWorkedExample, Qva) { EXPECT_NEAR(q_(1, 2), 4.09789258e-16, 0.5e-8 * 1e-16); }
TEST_F(GaussMarkovWorkedExample, Qaa) { EXPECT_NEAR(q_(2, 2), 8.19597488e-17, 0.5e-8 * 1e-17); }

TEST(GaussMarkov, NoiseIsSymmetric) {
  for (int k = -8; k <= 2; ++k) {
    const double x = std::pow(10.0, k);
    const Eigen::Matrix3d q = gauss_markov_chain(kDt, kDt / x, kSigma).noise;
    EXPECT_TRUE(q == q.transpose()) << "x = " << x;
  }
}

// Q is the covariance of a nondegenerate Gaussian (the noise drives a controllable chain), so it
// is positive definite for every dt > 0; cancellation in the naive closed forms breaks this.
TEST(GaussMarkov, NoiseIsPositiveDefinite) {
  for (int k = -80; k <= 20; ++k) {  // x = 10^(k/10), 1e-8 .. 100
    const double x = std::pow(10.0, k / 10.0);
    const Eigen::LLT<Eigen::Matrix3d> llt(gauss_markov_chain(kDt, kDt / x, kSigma).noise);
    EXPECT_EQ(llt.info(), Eigen::Success) << "x = " << x;
  }
}

// tau -> infinity (x = 1e-6): the integrated random walk (white-noise jerk) with PSD q,
// Q = q [[dt^5/20, dt^4/8, dt^3/6], [., dt^3/3, dt^2/2], [., ., dt]]. The relative deviation is
// first order in x with coefficients -5/9, -2/3, -1, -3/4, -1, -1 (Taylor series of the header's
// h_ij), so each ratio lies within x of 1.
TEST(GaussMarkov, SmallStepGivesIntegratedRandomWalk) {
  const double x = 1e-6, tau = kDt / x, q = 2.0 * kSigma * kSigma / tau, dt = kDt;
  Eigen::Matrix3d irw;
  irw << std::pow(dt, 5) / 20.0, std::pow(dt, 4) / 8.0, std::pow(dt, 3) / 6.0,
         std::pow(dt, 4) / 8.0, std::pow(dt, 3) / 3.0, dt * dt / 2.0,
         std::pow(dt, 3) / 6.0, dt * dt / 2.0, dt;
  irw *= q;
  EXPECT_LE(max_relative_error(gauss_markov_chain(dt, tau, kSigma).noise, irw), x);
}

// x -> infinity: the acceleration decorrelates within the step, its variance is the stationary one.
TEST(GaussMarkov, LongStepGivesStationaryAccelerationVariance) {
  const double q_aa = gauss_markov_chain(kDt, kDt / 100.0, kSigma).noise(2, 2);
  EXPECT_NEAR(q_aa, kSigma * kSigma, 1e-15 * kSigma * kSigma);  // sigma^2 (1 - e^-200)
}

// x -> infinity: v integrates an acceleration that acts as white noise of PSD q tau^2 = 2 sigma^2
// tau, so Q_vv -> 2 sigma^2 tau dt; h_vv / x = 1 - (2 (1 - E1) - (1 - E2) / 2) / x -> 1 - 1.5 / x.
TEST(GaussMarkov, LongStepGivesVelocityRandomWalk) {
  const double x = 100.0, tau = kDt / x;
  const double ratio = gauss_markov_chain(kDt, tau, kSigma).noise(1, 1) / (2.0 * kSigma * kSigma * tau * kDt);
  EXPECT_NEAR(ratio, 1.0 - 1.5 / x, 1e-14);
}

// Two steps of dt equal one of 2 dt (exact discretisation of a time-invariant system):
// Phi(2dt) = Phi Phi, Q(2dt) = Phi Q Phi' + Q. Checked across both branches and the switch
// (x = 1 -> 2 dt at x = 2; x = 0.75 -> 1.5).
TEST(GaussMarkov, TwoStepsComposeToOneDoubleStep) {
  for (double x : {1e-8, 1e-6, 1e-4, 1e-2, 0.1, 0.75, 1.0, 10.0, 100.0}) {
    SCOPED_TRACE(x);
    const double tau = kDt / x;
    const GaussMarkovChain one = gauss_markov_chain(kDt, tau, kSigma);
    const GaussMarkovChain two = gauss_markov_chain(2.0 * kDt, tau, kSigma);
    const Eigen::Matrix3d composed = one.transition * one.noise * one.transition.transpose() + one.noise;
    EXPECT_LE(max_relative_error(composed, two.noise), 1e-12);
  }
}

TEST(GaussMarkov, TwoTransitionsComposeToOneDoubleStep) {
  for (double x : {1e-8, 1e-6, 1e-4, 1e-2, 0.1, 0.75, 1.0, 10.0, 100.0}) {
    SCOPED_TRACE(x);
    const double tau = kDt / x;
    const Eigen::Matrix3d phi = gauss_markov_chain(kDt, tau, kSigma).transition;
    EXPECT_LE(max_relative_error(phi * phi, gauss_markov_chain(2.0 * kDt, tau, kSigma).transition), 1e-12);
  }
}

TEST(GaussMarkov, ZeroSigmaGivesZeroNoise) {
  EXPECT_TRUE(gauss_markov_chain(kDt, 600.0, 0.0).noise.isZero(0.0));
}

std::string error_field(const core::Status& e) { return e ? "none" : e.path(); }

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(GaussMarkovCheck, AcceptsTypicalValues) { EXPECT_EQ(error_field(check_gauss_markov(600.0, 5e-8)), "none"); }
TEST(GaussMarkovCheck, AcceptsZeroSigma) { EXPECT_EQ(error_field(check_gauss_markov(600.0, 0.0)), "none"); }
TEST(GaussMarkovCheck, RejectsZeroTau) { EXPECT_EQ(error_field(check_gauss_markov(0.0, 5e-8)), "empirical_tau_s"); }
TEST(GaussMarkovCheck, RejectsNegativeTau) { EXPECT_EQ(error_field(check_gauss_markov(-600.0, 5e-8)), "empirical_tau_s"); }
TEST(GaussMarkovCheck, RejectsNanTau) { EXPECT_EQ(error_field(check_gauss_markov(kNan, 5e-8)), "empirical_tau_s"); }
TEST(GaussMarkovCheck, RejectsInfiniteTau) { EXPECT_EQ(error_field(check_gauss_markov(kInf, 5e-8)), "empirical_tau_s"); }
TEST(GaussMarkovCheck, RejectsNegativeSigma) { EXPECT_EQ(error_field(check_gauss_markov(600.0, -5e-8)), "empirical_sigma_mps2"); }
TEST(GaussMarkovCheck, RejectsNanSigma) { EXPECT_EQ(error_field(check_gauss_markov(600.0, kNan)), "empirical_sigma_mps2"); }
TEST(GaussMarkovCheck, RejectsInfiniteSigma) { EXPECT_EQ(error_field(check_gauss_markov(600.0, kInf)), "empirical_sigma_mps2"); }

}  // namespace
}  // namespace visors::nav

namespace visors::nav {
namespace {

// white_equivalent_factor against its limits and against a simulated AR(1) sequence: the variance
// of the mean of N samples (independent method: 4,000 sequences of N = 2,000, tau = 20 samples)
// is sigma^2 factor / N within the Monte Carlo's 2.2 % (1 sigma, chi-square on 4,000 draws: 3.5
// sigma allowed) and the end effect (the factor is N's limit; at N = 100 tau the finite-N
// correction is 2 tau / N ~ 1 %).
TEST(WhiteEquivalentFactor, IsOneWithoutCorrelation) { EXPECT_NEAR(white_equivalent_factor(1.0, 1e-3), 1.0, 1e-12); }

TEST(WhiteEquivalentFactor, IsTwiceTauOverTheIntervalForLongCorrelation) {
  EXPECT_NEAR(white_equivalent_factor(1.0, 1e4) / 2e4, 1.0, 1e-8);
}

TEST(WhiteEquivalentFactor, GivesTheVarianceOfTheMeanOfAGaussMarkovSequence) {
  constexpr int kSequences = 4000, kSamples = 2000;
  constexpr double kTau = 20.0;
  const double phi = std::exp(-1.0 / kTau);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss;
  double sum_squares = 0.0;
  for (int k = 0; k < kSequences; ++k) {
    double e = gauss(rng), sum = 0.0;  // stationary start, unit variance
    for (int i = 0; i < kSamples; ++i) {
      sum += e;
      e = phi * e + std::sqrt(1.0 - phi * phi) * gauss(rng);
    }
    sum_squares += std::pow(sum / kSamples, 2);
  }
  const double variance_of_mean = sum_squares / kSequences;
  const double finite_n = 1.0 - 2.0 * phi * (1.0 - std::pow(phi, kSamples)) / (kSamples * (1.0 - phi * phi));
  EXPECT_NEAR(variance_of_mean * kSamples / (white_equivalent_factor(1.0, kTau) * finite_n), 1.0, 3.5 * 0.0224);
}

}  // namespace
}  // namespace visors::nav
