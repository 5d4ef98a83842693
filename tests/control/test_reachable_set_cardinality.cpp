// The reachable-set planner with fewer than six impulses
// (docs/algorithms/control.md#fewer-than-six-impulses): max_impulses is a cardinality constraint,
// so every k in 1..6 must give either a plan that reaches the target in the linear model or a
// clear failure, never ok with a miss (the reduction once read stale columns and
// returned ok with a 180 m miss at k = 1). References: an exhaustive search over every pair of
// the planner's own grid times written here independently (dynamic-size QR solves of the same
// linear model), and the 6-impulse optimum, below which no k-impulse plan can be.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Dense>

#include "visors/astro/roe_stm.hpp"
#include "visors/control/impulse_effect.hpp"
#include "control/mission.hpp"
#include "visors/control/reachable_set_planner.hpp"

namespace visors::control {
namespace {

using test::mission_chief;
using test::period_s;
using test::roe_m;
using test::science;
using test::standby;

const core::EarthGravityConstants kGravity{};

struct Case {
  const char* name;
  astro::RelativeOrbitalElements roe0;
  astro::RelativeOrbitalElements target;
  double tf_orbits;
};

std::vector<Case> cases() {
  return {
      {"standby_to_science_1.5orbits", standby(), science(), 1.5},
      {"science_trim_1orbit", science(), roe_m(-2.0, 44.0, -33.5, 5.5, -18.9, 2.5), 1.0},
      {"in_plane_only_2orbits", roe_m(0, 0, 0, 200, 0, 0), roe_m(0, 30, 0, 150, 0, 0), 2.0},
  };
}

ReachableSetPlanner planner_with(int max_impulses) {
  ReachableSetSettings s;
  s.max_impulses = max_impulses;
  return ReachableSetPlanner::create(s).value();
}

double terminal_miss_m(const Case& c, const ManeuverPlan& plan) {
  const double tf = c.tf_orbits * period_s();
  const auto final_roe = predict_roe(mission_chief(), c.roe0, plan.impulses, tf, kGravity);
  return mission_chief().a * (final_roe - c.target).norm();
}

// Exhaustive two-impulse optimum over the planner's grid (same times: t_earliest = 0, grid_points
// equally spaced, both ends), each pair a 6x6 system solved by column-pivoting QR [m/s].
double exhaustive_pair_optimum(const Case& c, int grid_points) {
  const double tf = c.tf_orbits * period_s();
  const Eigen::VectorXd w = mission_chief().a * (c.target - astro::j2_roe_stm(mission_chief(), tf, kGravity) * c.roe0);
  std::vector<Eigen::MatrixXd> b;
  for (int k = 0; k < grid_points; ++k) {
    const double t = k == grid_points - 1 ? tf : tf * k / (grid_points - 1);
    b.emplace_back(mission_chief().a * impulse_effect(mission_chief(), t, tf, kGravity));
  }
  double best = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd m(6, 6);
  for (int p = 0; p < grid_points; ++p) {
    for (int q = p + 1; q < grid_points; ++q) {
      m << b[p], b[q];
      const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
      if (qr.rank() < 6) continue;
      const Eigen::VectorXd x = qr.solve(w);
      if ((m * x - w).norm() > 1e-6 * w.norm()) continue;
      best = std::min(best, x.head(3).norm() + x.tail(3).norm());
    }
  }
  return best;
}

double six_impulse_cost(const Case& c) {
  auto planner = planner_with(6);
  return planner.plan(mission_chief(), c.roe0, c.target, 0.0, c.tf_orbits * period_s()).value().dv_total_mps;
}

// Every ok plan, for every k, reaches the target within 1 mm (the planner's terminal_tolerance_m)
// with at most k impulses; a failure names the field.
TEST(ReachableSetCardinality, EveryOkPlanReachesTheTargetWithinOneMillimetre) {
  for (const Case& c : cases()) {
    for (int k = 1; k <= 6; ++k) {
      SCOPED_TRACE(std::string(c.name) + " k=" + std::to_string(k));
      auto planner = planner_with(k);
      const auto plan = planner.plan(mission_chief(), c.roe0, c.target, 0.0, c.tf_orbits * period_s());
      if (!plan.ok()) {
        EXPECT_EQ(plan.error().field, "max_impulses") << plan.error().describe();
        continue;
      }
      // max_impulses is a cardinality constraint (reachable_set_planner.hpp); measured 2 .. 6 impulses for k = 2 .. 6 (2026-11)
      EXPECT_LE(plan->impulses.size(), static_cast<std::size_t>(k));
      EXPECT_LT(terminal_miss_m(c, *plan), 1e-3);
    }
  }
}

// One impulse has three unknowns for six conditions: a general change is a clear failure.
TEST(ReachableSetCardinality, OneImpulseRefusesAGeneralChange) {
  auto planner = planner_with(1);
  const auto plan = planner.plan(mission_chief(), standby(), science(), 0.0, 1.5 * period_s());
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().field, "max_impulses");
}

// ... but a target that one impulse at a grid time produces is found, at that time, with that dv.
TEST(ReachableSetCardinality, OneImpulseFindsATargetOneImpulseMade) {
  const double tf = 1.5 * period_s();
  const double t_burn = tf * 100.0 / 240.0;  // grid point 100 of the default 241
  const Eigen::Vector3d dv_rtn(0.002, -0.01, 0.004);
  const std::vector<Impulse> made{{t_burn, dv_rtn}};
  const auto target = predict_roe(mission_chief(), standby(), made, tf, kGravity);
  auto planner = planner_with(1);
  const auto plan = planner.plan(mission_chief(), standby(), target, 0.0, tf);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  ASSERT_EQ(plan->impulses.size(), 1u);
  // the grid time and dv that made the target (comment above); time measured 0; loose: dv measured 1.0e-17 m/s (2026-11), bound 1e-9 m/s ~1e8x above
  EXPECT_NEAR(plan->impulses[0].t, t_burn, 1e-6);
  EXPECT_LT((plan->impulses[0].dv_rtn - dv_rtn).norm(), 1e-9);
}

// k = 2 within 0.5 % of the exhaustive two-impulse optimum on the same grid (the acceptance
// criterion of the two-impulse search).
TEST(ReachableSetCardinality, TwoImpulsesMatchTheExhaustivePairSearch) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    auto planner = planner_with(2);
    const auto plan = planner.plan(mission_chief(), c.roe0, c.target, 0.0, c.tf_orbits * period_s());
    ASSERT_TRUE(plan.ok()) << plan.error().describe();
    const double reference = exhaustive_pair_optimum(c, planner.settings().grid_points);
    EXPECT_NEAR(plan->dv_total_mps, reference, 5e-3 * reference);
  }
}

// No k-impulse plan is cheaper than the 6-impulse optimum (up to the SOCP's 1e-4 relative
// accuracy), and 3..5 impulses never cost more than the best pair.
TEST(ReachableSetCardinality, FewerImpulsesNeverBeatTheOptimumAndMoreNeverLoseToTwo) {
  for (const Case& c : cases()) {
    const double optimum = six_impulse_cost(c);
    auto two = planner_with(2);
    const double pair = two.plan(mission_chief(), c.roe0, c.target, 0.0, c.tf_orbits * period_s()).value().dv_total_mps;
    EXPECT_GE(pair, optimum * (1.0 - 1e-4)) << c.name;
    for (int k = 3; k <= 5; ++k) {
      SCOPED_TRACE(std::string(c.name) + " k=" + std::to_string(k));
      auto planner = planner_with(k);
      const auto plan = planner.plan(mission_chief(), c.roe0, c.target, 0.0, c.tf_orbits * period_s());
      ASSERT_TRUE(plan.ok()) << plan.error().describe();
      EXPECT_GE(plan->dv_total_mps, optimum * (1.0 - 1e-4));
      EXPECT_LE(plan->dv_total_mps, pair * (1.0 + 1e-9));
    }
  }
}

}  // namespace
}  // namespace visors::control
