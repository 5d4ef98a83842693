// Reachable-set (dual) planner of Koenig & D'Amico 2021
// (docs/algorithms/control.md#reachable-set-planner) against a brute-force reference: the same
// minimum-fuel problem on a 10x finer time grid, solved as ONE conic program with every grid
// constraint at once (no working set, no exchange, no time refinement), whose
// primal impulses (the cone multipliers) are checked for feasibility and whose primal cost is
// checked against its dual objective, so the reference value is certified optimal for the dense
// grid by the duality gap.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <numbers>
#include <vector>

#include <Eigen/Dense>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/roe_stm.hpp"
#include "control/mission.hpp"
#include "visors/control/impulse_effect.hpp"
#include "visors/control/reachable_set_planner.hpp"
#include "visors/optim/conic_solver.hpp"
#include "support/temp_file.hpp"

namespace visors::control {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
const core::EarthGravityConstants kGravity{};

using test::mission_chief;
using test::period_s;
using test::roe_m;
using test::science;
using test::standby;

struct Reference {
  double dv = 0.0;          // dense-grid optimum [m/s] (dual objective)
  double primal_dv = 0.0;   // sum of the recovered impulse norms [m/s]
  double residual_m = 0.0;  // |sum B_k dv_k - a w| of the recovered impulses [m]
  bool optimal = false;
};

// Full dual over `points` grid times: max w'lambda s.t. ||B_k' lambda|| <= 1 for every k, scaled
// as in the planner (B by n, w to unit length). Impulses dv_k = -z_k(1:3) (G rows [0; -B_k']).
Reference dense_reference(const astro::RelativeOrbitalElements& roe0, const astro::RelativeOrbitalElements& target,
                          double t_earliest, double tf, int points) {
  const astro::KeplerianElements chief = mission_chief();
  const double a = chief.a;
  const double n = std::sqrt(kGravity.mu / (a * a * a));
  const Eigen::Matrix<double, 6, 1> w = a * (target - astro::j2_roe_stm(chief, tf, kGravity) * roe0);
  const double wn = w.norm();
  std::vector<Eigen::Matrix<double, 6, 3>> b(static_cast<std::size_t>(points));
  optim::ConicDimensions dims;
  dims.n = 6;
  dims.q.assign(static_cast<std::size_t>(points), 4);
  optim::ConicProblem pr;
  pr.c = -w / wn;
  pr.G = Eigen::MatrixXd::Zero(4 * points, 6);
  pr.h = Eigen::VectorXd::Zero(4 * points);
  pr.A.resize(0, 6);
  pr.b.resize(0);
  for (int k = 0; k < points; ++k) {
    const double t = t_earliest + (tf - t_earliest) * k / (points - 1.0);
    b[static_cast<std::size_t>(k)] = (chief.a * impulse_effect(chief, t, tf, kGravity));
    pr.G.block(4 * k + 1, 0, 3, 6) = -n * b[static_cast<std::size_t>(k)].transpose();
    pr.h(4 * k) = 1.0;
  }
  auto solver = optim::ConicSolver::create(dims);
  Reference ref;
  if (!solver.ok()) return ref;
  optim::ConicSolver s = std::move(solver).value();
  const auto info = s.solve(pr);
  if (!info.ok() || info->status != optim::ConicStatus::kOptimal) return ref;
  ref.optimal = true;
  ref.dv = -info->primal_objective * n * wn;
  Eigen::Matrix<double, 6, 1> reached = Eigen::Matrix<double, 6, 1>::Zero();
  for (int k = 0; k < points; ++k) {
    const Eigen::Vector3d dv = -s.z().segment<3>(4 * k + 1) * n * wn;
    ref.primal_dv += dv.norm();
    reached += b[static_cast<std::size_t>(k)] * dv;
  }
  ref.residual_m = (reached - w).norm();
  return ref;
}

ReachableSetPlanner make_planner(const ReachableSetSettings& settings = {}) {
  auto planner = ReachableSetPlanner::create(settings);
  EXPECT_TRUE(planner.ok()) << planner.error().describe();
  return std::move(planner).value();
}

struct Case {
  const char* name;
  astro::RelativeOrbitalElements roe0;
  astro::RelativeOrbitalElements target;
  double t_earliest_orbits;
  double tf_orbits;
  [[nodiscard]] double t0() const { return t_earliest_orbits * period_s(); }  // [s]
  [[nodiscard]] double tf() const { return tf_orbits * period_s(); }         // [s]
};

core::Result<ManeuverPlan> plan_case(ReachableSetPlanner& planner, const Case& c) {
  return planner.plan(mission_chief(), c.roe0, c.target, c.t0(), c.tf());
}

std::vector<Case> cases() {
  return {
      {"standby_to_science_1orbit", standby(), science(), 0.0, 1.0},
      {"standby_to_science_1.5orbits", standby(), science(), 0.0, 1.5},
      {"standby_to_science_0.5orbit", standby(), science(), 0.0, 0.5},
      {"science_to_standby_1orbit", science(), standby(), 0.0, 1.0},
      {"science_to_standby_late_start", science(), standby(), 0.2, 0.9},
      // Along-track dominated (the dlambda-dominant case: burns at the window ends).
      {"dlambda_dominant_0.4orbit", science(), roe_m(-2.62, 95.21, -34.51, 4.78, -18.72, 2.72), 0.0, 0.4},
      // Small science-orbit trim over a quarter orbit (radial burns are efficient there).
      {"science_trim_0.25orbit", science(), roe_m(-2.0, 44.0, -33.5, 5.5, -18.9, 2.5), 0.0, 0.25},
  };
}

// Acceptance (a): total delta-v within 0.5% of the dense-grid reference (10x the planner grid).
TEST(ReachableSetPlanner, TotalDeltaVWithinHalfPercentOfDenseGridReference) {
  ReachableSetPlanner planner = make_planner();
  const int dense = 10 * (planner.settings().grid_points - 1) + 1;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const double t0 = c.t0();
    const double tf = c.tf();
    const auto plan = plan_case(planner, c);
    ASSERT_TRUE(plan.ok()) << plan.error().describe();
    const Reference ref = dense_reference(c.roe0, c.target, t0, tf, dense);
    ASSERT_TRUE(ref.optimal);
    // The reference is certified: its impulses meet the target and cost what the dual says.
    // loose: residual measured 9.3e-12 m (2026-11), bound 1e-4 m ~1e7x above; duality gap: solver relative_gap_tolerance 1e-8 (conic_settings.hpp), loose: measured 3.1e-9 relative, bound 1e-6 ~320x above
    EXPECT_LT(ref.residual_m, 1e-4);
    EXPECT_NEAR(ref.primal_dv, ref.dv, 1e-6 * ref.dv);
    EXPECT_NEAR(plan->dv_total_mps, ref.dv, 5e-3 * ref.dv);
    std::printf("[ %-30s] planner %.6f m/s (%zu impulses, lb %.6f), dense %.6f m/s, gap %+.4f%%, %d exch\n", c.name,
                plan->dv_total_mps, plan->impulses.size(), plan->dv_lower_bound_mps, ref.dv,
                100.0 * (plan->dv_total_mps / ref.dv - 1.0), planner.stats().exchange_iterations);
  }
}

// Acceptance (b), linear part: the impulses reach the target in the planner's linear model to
// 1e-6 m (a * droe), recomputed independently of the planner's own prediction.
TEST(ReachableSetPlanner, ReachesTargetInLinearModelToMicrometres) {
  ReachableSetPlanner planner = make_planner();
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const double tf = c.tf_orbits * period_s();
    const auto plan = planner.plan(mission_chief(), c.roe0, c.target, c.t_earliest_orbits * period_s(), tf);
    ASSERT_TRUE(plan.ok()) << plan.error().describe();
    const auto final_roe = predict_roe(mission_chief(), c.roe0, plan->impulses, tf, kGravity);
    EXPECT_LT(mission_chief().a * (final_roe - c.target).norm(), 1e-6);
    EXPECT_LT(mission_chief().a * (plan->roe_final_predicted - final_roe).norm(), 1e-6);
  }
}

// Independent oracle (the same acceptance as above, another solver): CVXOPT's conelp
// (python3-cvxopt, as tests/optim/cvxopt_oracle.py uses it) at tolerances 1e-9 (looser if it fails) on the dense-grid
// problem in its dual form  max w'lambda s.t. ||B_k' lambda|| <= 1 for all k  (6 variables;
// conelp on the 4K-variable primal takes minutes at K = 2410 because its KKT system is dense),
// whose optimum equals the primal's by strong duality; the dual objective also bounds the primal
// from below, so plan cost >= 0.995 * oracle also certifies the 0.5% claim independently.
constexpr const char* kCvxoptDual = R"(
import sys
import numpy as np
from cvxopt import matrix, solvers
d = np.loadtxt(sys.argv[1])
w = d[0, :]
K = (d.shape[0] - 1) // 3
G = np.zeros((4 * K, 6))
h = np.zeros(4 * K)
for k in range(K):
    G[4 * k + 1:4 * k + 4, :] = -d[1 + 3 * k:4 + 3 * k, :]
    h[4 * k] = 1.0
# conelp can stop in its scaling update (math domain error) near the optimum at the tightest
# tolerances on this many cones; fall back to looser ones.
for tol in (1e-9, 1e-8, 1e-7):
    solvers.options.update({'show_progress': False, 'abstol': tol, 'reltol': tol, 'feastol': tol})
    try:
        sol = solvers.conelp(matrix(-w), matrix(G), matrix(h), {'l': 0, 'q': [4] * K, 's': []})
    except ValueError:
        continue
    if sol['status'] == 'optimal':
        print(sol['status'], -sol['primal objective'], tol)
        break
else:
    print('failed', -1)
)";

// Returns the CVXOPT optimum [m/s] of the dense-grid problem, or -1 when the oracle is unusable.
double cvxopt_dense_optimum(const astro::RelativeOrbitalElements& roe0, const astro::RelativeOrbitalElements& target,
                           double t_earliest, double tf, int points) {
  const astro::KeplerianElements chief = mission_chief();
  const double a = chief.a;
  const double n = std::sqrt(kGravity.mu / (a * a * a));
  const Eigen::Matrix<double, 6, 1> w = a * (target - astro::j2_roe_stm(chief, tf, kGravity) * roe0);
  std::ostringstream data;
  data.precision(17);
  for (int i = 0; i < 6; ++i) data << w(i) / w.norm() << (i < 5 ? " " : "\n");
  for (int k = 0; k < points; ++k) {
    const double t = t_earliest + (tf - t_earliest) * k / (points - 1.0);
    const Eigen::Matrix<double, 3, 6> bt = n * (chief.a * impulse_effect(chief, t, tf, kGravity)).transpose();
    for (int r = 0; r < 3; ++r) {
      for (int i = 0; i < 6; ++i) data << bt(r, i) << (i < 5 ? " " : "\n");
    }
  }
  const ::visors::test::TempFile script(kCvxoptDual, ".py");
  const ::visors::test::TempFile input(data.str(), ".txt");
  const std::string command = "/usr/bin/python3 '" + script.path().string() + "' '" + input.path().string() + "'";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return -1.0;
  char status[64] = {0};
  double objective = -1.0;
  const int read = std::fscanf(pipe, "%63s %lf", status, &objective);
  ::pclose(pipe);
  if (read != 2 || std::string(status) != "optimal") {
    std::printf("CVXOPT: read %d, status %s, objective %g\n", read, status, objective);
    return -1.0;
  }
  return objective * n * w.norm();
}

TEST(ReachableSetPlanner, TotalDeltaVWithinHalfPercentOfCvxoptDenseOptimum) {
  ASSERT_TRUE(std::filesystem::exists("/usr/bin/python3")) << "python3-cvxopt is installed by scripts/install-deps.sh";
  ReachableSetPlanner planner = make_planner();
  const int dense = 10 * (planner.settings().grid_points - 1) + 1;
  for (const Case& c : {cases()[0], cases()[2], cases()[5]}) {
    SCOPED_TRACE(c.name);
    const double t0 = c.t0();
    const double tf = c.tf();
    const auto plan = plan_case(planner, c);
    ASSERT_TRUE(plan.ok()) << plan.error().describe();
    const double oracle = cvxopt_dense_optimum(c.roe0, c.target, t0, tf, dense);
    // oracle contract: returns -1 when unusable (comment below); measured 0.032 .. 0.347 m/s (2026-11)
    ASSERT_GT(oracle, 0.0) << "CVXOPT oracle failed";
    EXPECT_NEAR(plan->dv_total_mps, oracle, 5e-3 * oracle);
    std::printf("[ %-30s] planner %.6f m/s, CVXOPT dense optimum %.6f m/s, gap %+.4f%%\n", c.name, plan->dv_total_mps, oracle,
                100.0 * (plan->dv_total_mps / oracle - 1.0));
  }
}

// Structure: at most max_impulses impulses, sorted, inside the window; dv_total is their sum.
TEST(ReachableSetPlanner, PlanHasAtMostSixSortedImpulsesInsideTheWindow) {
  ReachableSetPlanner planner = make_planner();
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const double t0 = c.t0();
    const double tf = c.tf();
    const auto plan = plan_case(planner, c);
    ASSERT_TRUE(plan.ok()) << plan.error().describe();
    EXPECT_LE(plan->impulses.size(), 6u);
    EXPECT_TRUE(validate_impulses(plan->impulses, t0, tf).ok());
    EXPECT_NEAR(plan->dv_total_mps, total_delta_v(plan->impulses), 1e-15);
  }
}

// Weak duality (Koenig & D'Amico 2021): dv_lower_bound never exceeds the optimum of the planner's
// own grid (the reference on that same grid), and the exchange closes the gap to 1e-6.
TEST(ReachableSetPlanner, LowerBoundIsTightOnThePlannerGrid) {
  ReachableSetPlanner planner = make_planner();
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const double t0 = c.t0();
    const double tf = c.tf();
    const auto plan = plan_case(planner, c);
    ASSERT_TRUE(plan.ok()) << plan.error().describe();
    const Reference grid = dense_reference(c.roe0, c.target, t0, tf, planner.settings().grid_points);
    ASSERT_TRUE(grid.optimal);
    EXPECT_LE(plan->dv_lower_bound_mps, grid.dv * (1.0 + 1e-6));
    EXPECT_GE(plan->dv_lower_bound_mps, grid.dv * (1.0 - 1e-5));
  }
}

// The worked example docs/algorithms/control.md#worked-example-standby-to-science gives the
// Keplerian near-circular optimum of standby -> science over 1.5 orbits as 0.10971 m/s
// (tangential, in plane) plus 0.21933 m/s (normal); the 3-D reachable-set optimum with J2 and
// radial burns allowed can only be cheaper than their sum (0.32904) and not cheaper than the
// larger of the two (a 3-D impulse costs at least its normal and its in-plane part).
TEST(ReachableSetPlanner, StandbyToScienceBetweenDecoupledBounds) {
  ReachableSetPlanner planner = make_planner();
  const auto plan = planner.plan(mission_chief(), standby(), science(), 0.0, 1.5 * period_s());
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  EXPECT_LT(plan->dv_total_mps, 0.32904 * 1.01);
  EXPECT_GT(plan->dv_total_mps, 0.21933 * 0.99);
}

TEST(ReachableSetPlanner, OnTargetGivesAnEmptyPlan) {
  ReachableSetPlanner planner = make_planner();
  const double tf = period_s();
  // roe0 chosen so that its free drift ends on the target.
  const astro::RelativeOrbitalElements roe0 = astro::j2_roe_stm(mission_chief(), tf, kGravity).inverse() * science();
  const auto plan = planner.plan(mission_chief(), roe0, science(), 0.0, tf);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  EXPECT_TRUE(plan->impulses.empty());
}

// Acceptance (d): bad input -> named Error, never a crash.
TEST(ReachableSetPlanner, RejectsNonFiniteRoe) {
  ReachableSetPlanner planner = make_planner();
  astro::RelativeOrbitalElements bad = standby();
  bad(2) = std::nan("");
  const auto plan = planner.plan(mission_chief(), bad, science(), 0.0, period_s());
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().field, "roe0");
}

TEST(ReachableSetPlanner, RejectsNonFiniteTarget) {
  ReachableSetPlanner planner = make_planner();
  astro::RelativeOrbitalElements bad = science();
  bad(0) = std::numeric_limits<double>::infinity();
  const auto plan = planner.plan(mission_chief(), standby(), bad, 0.0, period_s());
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().field, "roe_target");
}

TEST(ReachableSetPlanner, RejectsInvalidChief) {
  ReachableSetPlanner planner = make_planner();
  astro::KeplerianElements chief = mission_chief();
  chief.e = 1.2;
  const auto plan = planner.plan(chief, standby(), science(), 0.0, period_s());
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().field, "chief_mean_t0.e");
}

TEST(ReachableSetPlanner, RejectsFinalTimeBeforeEarliestTime) {
  ReachableSetPlanner planner = make_planner();
  const auto plan = planner.plan(mission_chief(), standby(), science(), 100.0, 50.0);
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().field, "tf");
}

TEST(ReachableSetPlanner, RejectsNanTime) {
  ReachableSetPlanner planner = make_planner();
  const auto plan = planner.plan(mission_chief(), standby(), science(), std::nan(""), 50.0);
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().field, "t_earliest");
}

TEST(ReachableSetPlanner, RejectsHorizonBelowMinimum) {
  ReachableSetPlanner planner = make_planner();  // min_horizon_orbits = 0.1
  const auto plan = planner.plan(mission_chief(), standby(), science(), 0.0, 0.05 * period_s());
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().field, "horizon");
}

// With the horizon check disabled, a 6-D target over 1 s is out of reach (the B(t) are parallel):
// the dual box binds and the target is reported unreachable.
TEST(ReachableSetPlanner, ReportsUnreachableTarget) {
  ReachableSetSettings settings;
  settings.min_horizon_orbits = 0.0;
  ReachableSetPlanner planner = make_planner(settings);
  const auto plan = planner.plan(mission_chief(), standby(), science(), 0.0, 1.0);
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().field, "roe_target") << plan.error().describe();
}

TEST(ReachableSetPlanner, RejectsTooSmallGrid) {
  ReachableSetSettings settings;
  settings.grid_points = 3;
  const auto planner = ReachableSetPlanner::create(settings);
  ASSERT_FALSE(planner.ok());
  EXPECT_EQ(planner.error().field, "grid_points");
}

}  // namespace
}  // namespace visors::control
