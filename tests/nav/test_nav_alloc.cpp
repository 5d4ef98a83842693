// The ambiguity resolution allocates nothing after creation (issue 14, CONTRIBUTING "Memory"):
// this file counts every heap allocation of the test_nav executable
// (support/allocation_counter.hpp, malloc level) around decorrelation, search, partial search and
// acceptance, on 24-ambiguity dual-frequency problems and on the capacity-sized 64.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <random>

#include "nav/ambiguity_acceptance.hpp"
#include "nav/integer_least_squares.hpp"
#include "support/allocation_counter.hpp"
#include "support/dd_geometry.hpp"

namespace visors::nav {
namespace {

// (The counter's control tests, an Eigen dynamic matrix and a new, come with the header.)

struct Problem {
  Eigen::VectorXd a;
  Eigen::MatrixXd Q;
};

Problem dd_problem(int satellites, std::mt19937_64& rng) {
  test::DdGeometryOptions o;
  o.satellites = satellites;
  o.frequencies = 2;
  Problem p;
  p.Q = test::dd_ambiguity_covariance(o, rng);
  const Eigen::MatrixXd chol = p.Q.llt().matrixL();
  p.a = test::float_ambiguities(test::random_integers(p.Q.rows(), 1e6, rng), chol, rng);
  return p;
}

TEST(NavAllocation, ResolveAllocatesNothing) {
  auto ils = IntegerLeastSquares::create().value();
  std::mt19937_64 rng(3);
  for (int k = 0; k < 10; ++k) {
    const Problem p = dd_problem(13, rng);  // n = 24
    IlsStatus status = IlsStatus::kEmpty;
    EXPECT_EQ(test::count_allocations([&] { status = ils.resolve(p.a, p.Q); }), 0);
    EXPECT_EQ(status, IlsStatus::kOk);
  }
}

TEST(NavAllocation, PartialSearchAllocatesNothing) {
  auto ils = IntegerLeastSquares::create().value();
  std::mt19937_64 rng(4);
  const Problem p = dd_problem(13, rng);
  ASSERT_EQ(ils.decorrelate(p.a, p.Q), IlsStatus::kOk);
  IlsStatus status = IlsStatus::kEmpty;
  EXPECT_EQ(test::count_allocations([&] { status = ils.search(10); }), 0);
  EXPECT_EQ(status, IlsStatus::kOk);
}

TEST(NavAllocation, AcceptanceAllocatesNothing) {
  auto ils = IntegerLeastSquares::create().value();
  std::mt19937_64 rng(5);
  const Problem p = dd_problem(13, rng);
  AmbiguityFix fix;
  EXPECT_EQ(test::count_allocations([&] { fix = resolve_ambiguities(ils, p.a, p.Q, AcceptanceSettings{}); }), 0);
  EXPECT_NE(fix.reason, FloatReason::kInvalidInput);
}

TEST(NavAllocation, CapacitySizedProblemAllocatesNothing) {
  auto ils = IntegerLeastSquares::create().value();
  std::mt19937_64 rng(6);
  const Problem p = dd_problem(33, rng);  // n = 64 = kMaxAmbiguities
  ASSERT_EQ(p.a.size(), kMaxAmbiguities);
  IlsStatus status = IlsStatus::kEmpty;
  EXPECT_EQ(test::count_allocations([&] { status = ils.resolve(p.a, p.Q); }), 0);
  EXPECT_EQ(status, IlsStatus::kOk);
}

TEST(NavAllocation, RejectedInputAllocatesNothing) {
  auto ils = IntegerLeastSquares::create().value();
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(4, 4);
  Q(0, 1) = 0.5;  // not symmetric
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(4);
  IlsStatus status = IlsStatus::kOk;
  EXPECT_EQ(test::count_allocations([&] { status = ils.resolve(a, Q); }), 0);
  EXPECT_EQ(status, IlsStatus::kNotSymmetric);
}

}  // namespace
}  // namespace visors::nav
