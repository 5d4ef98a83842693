// Integer least squares (LAMBDA reduction + MLAMBDA search) against published results and an
// independent brute-force enumeration.
#include "nav/integer_least_squares.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "nav/bootstrap.hpp"

namespace visors::nav {
namespace {

// RTKLIB test/utest/t_lambda.c, utest1 (tomojitakasu/RTKLIB; navigation digest sec. 6.7): n = 6.
Eigen::MatrixXd utest1_q() {
  Eigen::MatrixXd Q = Eigen::MatrixXd::Constant(6, 6, 0.112202);
  Q.diagonal().setConstant(0.227134);
  Q(5, 5) = 0.434339;
  for (int i = 0; i < 5; ++i) Q(i, 5) = Q(5, i) = 0.103473;
  return Q;
}
Eigen::VectorXd utest1_a() {
  Eigen::VectorXd a(6);
  a << 1585184.171, -6716599.430, 3915742.905, 7627233.455, 9565990.879, 989457273.200;
  return a;
}

// utest2: n = 10, Q = [[A, B], [B, C]], 5 x 5 blocks with one diagonal and one off-diagonal value.
Eigen::MatrixXd utest2_q() {
  auto block = [](double diagonal, double off) {
    Eigen::MatrixXd b = Eigen::MatrixXd::Constant(5, 5, off);
    b.diagonal().setConstant(diagonal);
    return b;
  };
  Eigen::MatrixXd Q(10, 10);
  Q << block(0.446320, 0.223160), block(0.572775, 0.286388), block(0.572775, 0.286388), block(0.735063, 0.367531);
  return Q;
}
Eigen::VectorXd utest2_a() {
  Eigen::VectorXd a(10);
  a << -13324172.755747, -10668894.713608, -7157225.010770, -6149367.974367, -7454133.571066, -5969200.494550,
      8336734.058423, 6186974.084502, -17549093.883655, -13970158.922370;
  return a;
}

IntegerLeastSquares make_ils(int candidates = 2) {
  IlsSettings settings;
  settings.candidates = candidates;
  return IntegerLeastSquares::create(settings).value();
}

TEST(IntegerLeastSquares, RtklibUtest1BestCandidateIsExact) {
  auto ils = make_ils();
  ASSERT_EQ(ils.resolve(utest1_a(), utest1_q()), IlsStatus::kOk);
  Eigen::VectorXd best(6);
  best << 1585184, -6716599, 3915743, 7627234, 9565991, 989457273;  // t_lambda.c utest1 F1
  EXPECT_EQ(ils.solution().a.col(0), best);
}

TEST(IntegerLeastSquares, RtklibUtest1SecondCandidateIsExact) {
  auto ils = make_ils();
  ASSERT_EQ(ils.resolve(utest1_a(), utest1_q()), IlsStatus::kOk);
  Eigen::VectorXd second(6);
  second << 1585184, -6716600, 3915743, 7627233, 9565991, 989457273;  // t_lambda.c utest1 F2
  EXPECT_EQ(ils.solution().a.col(1), second);
}

TEST(IntegerLeastSquares, RtklibUtest1SquaredNorms) {
  auto ils = make_ils();
  ASSERT_EQ(ils.resolve(utest1_a(), utest1_q()), IlsStatus::kOk);
  // t_lambda.c utest1 s = (3.507984, 3.708456), checked there to 1e-4.
  EXPECT_NEAR(ils.solution().sqnorm(0), 3.507984, 1e-4);
  EXPECT_NEAR(ils.solution().sqnorm(1), 3.708456, 1e-4);
}

TEST(IntegerLeastSquares, RtklibUtest2BestCandidateIsExact) {
  auto ils = make_ils();
  ASSERT_EQ(ils.resolve(utest2_a(), utest2_q()), IlsStatus::kOk);
  Eigen::VectorXd best(10);  // t_lambda.c utest2 F1
  best << -13324188, -10668901, -7157236, -6149379, -7454143, -5969220, 8336726, 6186960, -17549108, -13970171;
  EXPECT_EQ(ils.solution().a.col(0), best);
}

TEST(IntegerLeastSquares, RtklibUtest2SecondCandidateIsExact) {
  auto ils = make_ils();
  ASSERT_EQ(ils.resolve(utest2_a(), utest2_q()), IlsStatus::kOk);
  Eigen::VectorXd second(10);  // t_lambda.c utest2 F2
  second << -13324188, -10668908, -7157236, -6149379, -7454143, -5969220, 8336717, 6186960, -17549108, -13970171;
  EXPECT_EQ(ils.solution().a.col(1), second);
}

TEST(IntegerLeastSquares, RtklibUtest2SquaredNorms) {
  auto ils = make_ils();
  ASSERT_EQ(ils.resolve(utest2_a(), utest2_q()), IlsStatus::kOk);
  // t_lambda.c utest2 s = (1506.435789, 1612.811795), to 1e-4 there; Q is nearly singular and the
  // digest's brute force gives 1506.435806 / 1612.811781 (2e-5 apart): 1e-4 covers both.
  EXPECT_NEAR(ils.solution().sqnorm(0), 1506.435789, 1e-4);
  EXPECT_NEAR(ils.solution().sqnorm(1), 1612.811795, 1e-4);
}

TEST(IntegerLeastSquares, Utest1BootstrappedSuccessRateAfterDecorrelation) {
  auto ils = make_ils();
  ASSERT_EQ(ils.decorrelate(utest1_a(), utest1_q()), IlsStatus::kOk);
  // Navigation digest sec. 6.7 (derived there, decorrelated): P_s,IB = 0.1743. The pivoted
  // reduction may reach a different (equally valid) basis; the bootstrapped rate of any reduced
  // basis must be at least the undecorrelated order's 0.1712 (digest) and close to 0.1743.
  EXPECT_NEAR(ils.success_rate_bootstrap(), 0.1743, 2e-3);
}

}  // namespace
}  // namespace visors::nav
