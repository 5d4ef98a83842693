// Flight-code memory rule (CONTRIBUTING "Memory"): after setup, the planners' "into" forms, the
// MPC step (replanning included) and the buffer allocate nothing; the value-returning forms only
// their result vector. This file counts every heap allocation of test_control (malloc level,
// support/allocation_counter.hpp, whose control tests prove Eigen's allocations are seen).

#include <gtest/gtest.h>

#include "visors/astro/j2_secular.hpp"
#include "visors/control/closed_form_planner.hpp"
#include "visors/control/impulse_effect.hpp"
#include "visors/control/least_squares_planner.hpp"
#include "visors/control/maneuver_buffer.hpp"
#include "control/mission.hpp"
#include "visors/control/reachable_set_planner.hpp"
#include "visors/control/stochastic_mpc.hpp"
#include "support/allocation_counter.hpp"

namespace visors::control {
namespace {

using visors::test::count_allocations;

TEST(ControlAllocation, ReachableSetPlanAllocatesOnlyItsResult) {
  ReachableSetPlanner planner = ReachableSetPlanner::create().value();
  bool ok = false;
  const long allocations = count_allocations([&] {
    ok = planner.plan(test::mission_chief(), test::standby(), test::science(), 0.0, test::period_s()).ok();
  });
  EXPECT_TRUE(ok);
  EXPECT_LE(allocations, 1);
}

// Every cardinality path (6: Caratheodory only; 4: greedy elimination and the pair search; 2: the
// pair search) into a plan with reserved capacity.
TEST(ControlAllocation, ReachableSetPlanIntoAllocatesNothingForEveryImpulseCount) {
  for (int k : {6, 4, 2}) {
    ReachableSetSettings s;
    s.max_impulses = k;
    ReachableSetPlanner planner = ReachableSetPlanner::create(s).value();
    ManeuverPlan plan;
    plan.impulses.reserve(6);
    bool ok = false;
    const long allocations = count_allocations([&] {
      ok = planner.plan_into(plan, test::mission_chief(), test::standby(), test::science(), 0.0, 1.5 * test::period_s())
               .ok();
    });
    EXPECT_TRUE(ok) << "k = " << k;
    EXPECT_EQ(allocations, 0) << "k = " << k;
  }
}

TEST(ControlAllocation, ClosedFormPlanIntoAllocatesNothing) {
  ManeuverPlan plan;
  plan.impulses.reserve(kMaxClosedFormImpulses);
  bool ok = false;
  const long allocations = count_allocations([&] {
    ok = plan_closed_form_into(plan, test::mission_chief(), test::standby(), test::science(), 2.0 * test::period_s())
             .ok();
  });
  EXPECT_TRUE(ok);
  EXPECT_EQ(allocations, 0);
}

TEST(ControlAllocation, LeastSquaresPlanIntoAllocatesNothing) {
  const double times[] = {100.0, 1500.0, 2800.0};
  LeastSquaresPlan out;
  out.plan.impulses.reserve(kMaxLeastSquaresBurns);
  bool ok = false;
  const long allocations = count_allocations([&] {
    ok = plan_least_squares_into(out, test::mission_chief(), test::science(), test::science(), 3400.0, times).ok();
  });
  EXPECT_TRUE(ok);
  EXPECT_EQ(allocations, 0);
}

// The first step plans; the second, after a 0.5 m along-track disturbance against a 1 mm
// navigation sigma, replans.
TEST(ControlAllocation, MpcStepIntoAllocatesNothingWhenItReplans) {
  StochasticMpcSettings settings;  // navigation-limited, so the disturbance is what decides
  settings.execution_sigma_fraction = 0.0;
  settings.execution_sigma_floor_mps = 0.0;
  StochasticMpc mpc = StochasticMpc::create(settings).value();
  ASSERT_TRUE(mpc.set_target(test::science(), test::period_s()).ok());
  MpcStep step;
  step.remaining.reserve(6);
  const Eigen::Matrix<double, 6, 6> covariance =
      Eigen::Matrix<double, 6, 6>::Identity() * std::pow(1e-3 / test::mission_chief().a, 2);
  core::Status first;
  long allocations = count_allocations(
      [&] { first = mpc.step_into(step, 0.0, test::mission_chief(), test::standby(), covariance); });
  ASSERT_TRUE(first.ok()) << first.error().describe();
  EXPECT_EQ(allocations, 0);
  // At t = 1500 s: the linear-model state with the burns done by then, plus 0.5 m along-track.
  const double t = 1500.0;
  std::vector<Impulse> done;
  for (const Impulse& i : step.remaining) {
    if (i.t < t) done.push_back(i);
  }
  // A named type, not auto: an Eigen sum of a temporary would dangle.
  const astro::RelativeOrbitalElements disturbed = predict_roe(test::mission_chief(), test::standby(), done, t) + test::roe_m(0, 0.5, 0, 0, 0, 0);
  const auto chief_t = astro::propagate_mean_j2(test::mission_chief(), t);
  core::Status second;
  allocations = count_allocations([&] { second = mpc.step_into(step, t, chief_t, disturbed, covariance); });
  ASSERT_TRUE(second.ok()) << second.error().describe();
  EXPECT_TRUE(step.replanned) << "d = " << step.mahalanobis;
  EXPECT_EQ(allocations, 0);
}

TEST(ControlAllocation, BufferingAnImpulseAllocatesNothing) {
  ImpulseBuffer buffer;
  const Impulse impulse{600.0, Eigen::Vector3d(0.004, 0.03, -0.01)};
  bool ok = false;
  const long allocations =
      count_allocations([&] { ok = buffer.buffer(test::mission_chief(), impulse, 10.62, BufferSettings{}).ok(); });
  const long again =
      count_allocations([&] { ok = buffer.buffer(test::mission_chief(), impulse, 10.62, BufferSettings{}).ok(); });
  EXPECT_EQ(again, 0);
  EXPECT_TRUE(ok);
  // precondition (the impulse must be split for the test to mean anything); measured 17 pieces (2026-11)
  EXPECT_GT(buffer.result().pieces.size(), 1u);
  EXPECT_EQ(allocations, 0);
}

}  // namespace
}  // namespace visors::control
