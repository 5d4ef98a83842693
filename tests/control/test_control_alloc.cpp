// Flight-code memory rule (CONTRIBUTING "Memory"): after setup, a planner call allocates only the
// impulse vector it returns (one allocation). This file counts every heap
// allocation of test_control (malloc level).

#include <gtest/gtest.h>

#include "control/closed_form_planner.hpp"
#include "control/least_squares_planner.hpp"
#include "control/mission.hpp"
#include "control/reachable_set_planner.hpp"
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

TEST(ControlAllocation, ClosedFormPlanAllocatesOnlyItsResult) {
  bool ok = false;
  const long allocations = count_allocations([&] {
    ok = plan_closed_form(test::mission_chief(), test::standby(), test::science(), 2.0 * test::period_s()).ok();
  });
  EXPECT_TRUE(ok);
  EXPECT_LE(allocations, 1);
}

TEST(ControlAllocation, LeastSquaresPlanAllocatesOnlyItsResult) {
  const double times[] = {100.0, 1500.0, 2800.0};
  bool ok = false;
  const long allocations = count_allocations([&] {
    ok = plan_least_squares(test::mission_chief(), test::science(), test::science(), 3400.0, times).ok();
  });
  EXPECT_TRUE(ok);
  EXPECT_LE(allocations, 1);
}

}  // namespace
}  // namespace visors::control
