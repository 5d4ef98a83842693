// Fix statistics that mean something: on simulated float solutions with known integers,
// each acceptance rule's empirical wrong-fix rate stays at or below the failure rate it promises
// (within binomial error), with the fix rate reported next to it (RecordProperty, in the XML of
// `ctest --output-junit` and printed).
//
// Every draw has its own single-epoch, single-frequency DD geometry (tests/support/dd_geometry.hpp)
// with n + 1 satellites, so Q changes from draw to draw as in a filter and the model-driven rules
// fix some draws and not others. Such geometries are strong (10+ satellites fix at once with
// 0.3 m code), so each case's code sigma is set by bisection to give the target bootstrapped
// success rate on a reference geometry: the draws then straddle P0 = 0.999, where acceptance
// matters. Promise of the success-rate rules: P(wrong and accepted) = E[1{P_IB(Q) >= P0}
// P_f,ILS(Q)] <= 1 - P0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "visors/nav/ambiguity_acceptance.hpp"
#include "visors/nav/integer_least_squares.hpp"
#include "support/dd_geometry.hpp"

namespace visors::nav {
namespace {

constexpr int kDraws = 10000;

struct Case {
  int n;
  double target_success_rate;
};

// Code sigma [m] that gives the target success rate on the case's reference geometry.
double calibrated_code_sigma(const Case& c, IntegerLeastSquares& ils) {
  test::DdGeometryOptions o;
  o.satellites = c.n + 1;
  o.frequencies = 1;
  double low = 0.01, high = 1000.0;
  for (int it = 0; it < 50; ++it) {
    o.code_sigma_m = std::sqrt(low * high);
    std::mt19937_64 rng(1000 + c.n);  // the same geometry at every trial sigma
    const Eigen::MatrixXd Q = test::dd_ambiguity_covariance(o, rng);
    EXPECT_EQ(ils.decorrelate(Eigen::VectorXd::Zero(c.n), Q), IlsStatus::kOk);
    (ils.success_rate_bootstrap() > c.target_success_rate ? low : high) = o.code_sigma_m;
  }
  return std::sqrt(low * high);
}

struct Tally {
  int fixed = 0;  // full or partial
  int wrong = 0;  // fixed with at least one wrong integer combination
};

// Whether the accepted integers equal the true ones: Z_k' z_true for the k trailing combinations.
bool correct(const IntegerLeastSquares& ils, const Eigen::VectorXd& z_true) {
  const IlsSolution& s = ils.solution();
  const auto& Z = ils.transformation();
  const Eigen::VectorXd expected = Z.block(0, s.n - s.fixed, s.n, s.fixed).transpose() * z_true;
  return expected == s.z.col(0);
}

Tally simulate(const Case& c, double code_sigma_m, const AcceptanceSettings& rule, IntegerLeastSquares& ils) {
  test::DdGeometryOptions o;
  o.satellites = c.n + 1;
  o.frequencies = 1;
  o.code_sigma_m = code_sigma_m;
  std::mt19937_64 rng(77 + c.n);
  Tally t;
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::MatrixXd Q = test::dd_ambiguity_covariance(o, rng);
    const Eigen::MatrixXd chol = Q.llt().matrixL();
    const Eigen::VectorXd z = test::random_integers(c.n, 1e6, rng);
    const Eigen::VectorXd a = test::float_ambiguities(z, chol, rng);
    const AmbiguityFix fix = resolve_ambiguities(ils, a, Q, rule);
    if (fix.outcome == FixOutcome::kFloat) continue;
    ++t.fixed;
    if (!correct(ils, z)) ++t.wrong;
  }
  return t;
}

class AcceptanceStatistics : public ::testing::TestWithParam<Case> {};

TEST_P(AcceptanceStatistics, SuccessRateRulesKeepTheirFailureRatePromise) {
  const Case c = GetParam();
  auto ils = IntegerLeastSquares::create().value();
  const double code_sigma_m = calibrated_code_sigma(c, ils);
  struct Named {
    const char* name;
    AcceptanceRule rule;
  };
  for (const Named r : {Named{"success_rate", AcceptanceRule::kSuccessRate}, Named{"success_rate_and_ratio", AcceptanceRule::kSuccessRateAndRatio},
                        Named{"ratio_only", AcceptanceRule::kRatio}}) {
    AcceptanceSettings settings;
    settings.rule = r.rule;
    const Tally t = simulate(c, code_sigma_m, settings, ils);
    const double fix_rate = static_cast<double>(t.fixed) / kDraws;
    const double wrong_rate = static_cast<double>(t.wrong) / kDraws;
    std::printf("n=%2d code %.3f m %-24s fix rate %.4f wrong-fix rate %.5f (%d of %d)\n", c.n, code_sigma_m, r.name,
                fix_rate, wrong_rate, t.wrong, kDraws);
    RecordProperty(std::string(r.name) + "_fix_rate", std::to_string(fix_rate));
    RecordProperty(std::string(r.name) + "_wrong_fix_rate", std::to_string(wrong_rate));
    if (r.rule == AcceptanceRule::kRatio) continue;  // a constant ratio threshold promises no rate
    // Promise: P(wrong and accepted) <= 1 - P0 (ILS succeeds at least as often as bootstrapping,
    // Teunissen 1999); allowance 3 binomial sigmas of a rate 1 - P0 over kDraws attempts.
    const double promise = 1.0 - settings.min_success_rate;
    const double allowance = 3.0 * std::sqrt(promise * (1.0 - promise) / kDraws);
    EXPECT_LE(wrong_rate, promise + allowance) << r.name;
  }
}

INSTANTIATE_TEST_SUITE_P(SingleFrequencyDd, AcceptanceStatistics,
                         ::testing::Values(Case{8, 0.999}, Case{12, 0.999}, Case{16, 0.999}, Case{24, 0.999}),
                         [](const ::testing::TestParamInfo<Case>& param) {
                           // Not "n" + to_string: GCC 12 warns (-Wrestrict, a known false positive) on that.
                           std::string name = std::to_string(param.param.n);
                           return name.insert(0, 1, 'n');
                         });

}  // namespace
}  // namespace visors::nav
