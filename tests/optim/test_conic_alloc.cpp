// solve() allocates nothing (conic_solver.hpp, CONTRIBUTING "Memory"): this file counts every heap allocation
// of the test_optim executable (support/allocation_counter.hpp) and
// checks that no allocation happens between the start and the end of solve(), on an SOCP of the
// planner's shape, a QP, and an LP that exercises the dense-LU fallback of the KKT solve.
#include <gtest/gtest.h>

#include <random>

#include "visors/optim/conic_solver.hpp"
#include "optim/minimum_fuel_problem.hpp"
#include "support/allocation_counter.hpp"

namespace {

using visors::optim::ConicDimensions;
using visors::optim::ConicProblem;
using visors::optim::ConicSettings;
using visors::optim::ConicSolver;
using visors::optim::ConicStatus;

long allocations_during_solve(ConicSolver& solver, const ConicProblem& problem, ConicStatus* status, int* fallbacks) {
  return visors::test::count_allocations([&] {
    const auto info = solver.solve(problem);
    *status = info.ok() ? info->status : ConicStatus::kNumericalError;
    *fallbacks = info.ok() ? info->dense_fallbacks : 0;
  });
}

// The harness sees allocations: setting a solver up allocates its workspace.
TEST(ConicAllocation, CounterSeesSetupAllocations) {
  ConicDimensions dims;
  dims.n = 4;
  dims.l = 4;
  bool ok = false;
  const long allocations = visors::test::count_allocations([&] { ok = ConicSolver::create(dims).ok(); });
  ASSERT_TRUE(ok);
  EXPECT_GT(allocations, 0);
}

TEST(ConicAllocation, SolveOfPlannerSocpAllocatesNothing) {
  std::mt19937 rng(7);
  auto created = ConicSolver::create(visors::optim::test::minimum_fuel_dimensions(30));
  ASSERT_TRUE(created.ok());
  ConicSolver solver = std::move(created).value();
  for (int trial = 0; trial < 3; ++trial) {  // first solve and re-solves with new data
    const ConicProblem pr = visors::optim::test::minimum_fuel_problem(30, rng);
    ConicStatus status{};
    int fallbacks = 0;
    EXPECT_EQ(allocations_during_solve(solver, pr, &status, &fallbacks), 0) << "trial " << trial;
    EXPECT_EQ(status, ConicStatus::kOptimal);
  }
}

// A random feasible LP with equality rows at tight tolerances: its last iterations need the
// dense LU fallback, which must not allocate either.
TEST(ConicAllocation, SolveWithDenseFallbackAllocatesNothing) {
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.1, 2.0);
  const int n = 23, m = 40, p = 9;
  ConicProblem pr;
  pr.G = Eigen::MatrixXd::NullaryExpr(m, n, [&] { return normal(rng); });
  pr.A = Eigen::MatrixXd::NullaryExpr(p, n, [&] { return normal(rng); });
  const Eigen::VectorXd x0 = Eigen::VectorXd::NullaryExpr(n, [&] { return normal(rng); });
  const Eigen::VectorXd s0 = Eigen::VectorXd::NullaryExpr(m, [&] { return uniform(rng); });
  const Eigen::VectorXd z0 = Eigen::VectorXd::NullaryExpr(m, [&] { return uniform(rng); });
  const Eigen::VectorXd y0 = Eigen::VectorXd::NullaryExpr(p, [&] { return normal(rng); });
  pr.h = pr.G * x0 + s0;
  pr.b = pr.A * x0;
  pr.c = -(pr.G.transpose() * z0 + pr.A.transpose() * y0);
  ConicDimensions dims;
  dims.n = n;
  dims.p = p;
  dims.l = m;
  ConicSettings settings;
  settings.feasibility_tolerance = settings.absolute_gap_tolerance = settings.relative_gap_tolerance = 1e-10;
  auto created = ConicSolver::create(dims, settings);
  ASSERT_TRUE(created.ok());
  ConicSolver solver = std::move(created).value();
  ConicStatus status{};
  int fallbacks = 0;
  EXPECT_EQ(allocations_during_solve(solver, pr, &status, &fallbacks), 0);
  EXPECT_EQ(status, ConicStatus::kOptimal);
  EXPECT_GT(fallbacks, 0) << "instance no longer exercises the fallback; pick another";
}

TEST(ConicAllocation, SolveOfQpAllocatesNothing) {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  const int n = 15, m = 20;
  ConicProblem pr;
  const Eigen::MatrixXd F = Eigen::MatrixXd::NullaryExpr(8, n, [&] { return normal(rng); });
  pr.P = F.transpose() * F;
  pr.c = Eigen::VectorXd::NullaryExpr(n, [&] { return normal(rng); });
  pr.G = Eigen::MatrixXd::NullaryExpr(m, n, [&] { return normal(rng); });
  pr.h = Eigen::VectorXd::Ones(m) + pr.G * Eigen::VectorXd::NullaryExpr(n, [&] { return normal(rng); });
  pr.A.resize(0, n);
  pr.b.resize(0);
  ConicDimensions dims;
  dims.n = n;
  dims.l = m;
  dims.quadratic = true;
  auto created = ConicSolver::create(dims);
  ASSERT_TRUE(created.ok());
  ConicSolver solver = std::move(created).value();
  ConicStatus status{};
  int fallbacks = 0;
  EXPECT_EQ(allocations_during_solve(solver, pr, &status, &fallbacks), 0);
  EXPECT_EQ(status, ConicStatus::kOptimal);
}

}  // namespace
