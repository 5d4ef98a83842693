// Flight-code memory rule (CONTRIBUTING "Memory"): evaluate_passive_safety allocates nothing.
// This file counts every heap allocation of test_safety
// (support/allocation_counter.hpp, to be included in exactly one file of the executable).
#include <gtest/gtest.h>

#include "visors/core/constants.hpp"
#include "visors/safety/passive_safety.hpp"
#include "visors/safety/escape_maneuver.hpp"
#include "support/allocation_counter.hpp"

namespace visors::safety {
namespace {

// The mission chief and the paper's science orbit (a*dROE in m), 1 m sigma per element.
const astro::KeplerianElements chief{6378136.3 + 500e3, 0.004, 97.8 * core::kDegToRad,
                                     157.5 * core::kDegToRad, 90.0 * core::kDegToRad, 0.0};
const astro::RelativeOrbitalElements roe =
    (astro::RelativeOrbitalElements() << -2.62, 45.21, -34.51, 4.78, -18.72, 2.72).finished() / chief.a;
const RoeCovariance p = RoeCovariance::Identity() / (chief.a * chief.a);

TEST(PassiveSafetyAlloc, EvaluationAllocatesNothing) {
  for (const SafetyPlane plane : {SafetyPlane::kRadialNormal, SafetyPlane::kThreeDimensional}) {
    PassiveSafetySettings s;
    s.plane = plane;
    bool ok = false;
    const long allocations =
        test::count_allocations([&] { ok = evaluate_passive_safety(chief, roe, p, s).ok(); });
    EXPECT_TRUE(ok);
    EXPECT_EQ(allocations, 0);
  }
}

// The escape planner (a search over candidate burn times, each with its safety check).
TEST(PassiveSafetyAlloc, EscapePlanningAllocatesNothing) {
  bool ok = false;
  const long allocations =
      test::count_allocations([&] { ok = plan_escape(chief, roe, p, 0.0, EscapeSettings{}).ok(); });
  EXPECT_TRUE(ok);
  EXPECT_EQ(allocations, 0);
}

}  // namespace
}  // namespace visors::safety
