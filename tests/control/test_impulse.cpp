// Impulse list helpers.
#include <gtest/gtest.h>

#include <cmath>

#include "control/impulse.hpp"

namespace visors::control {
namespace {

TEST(Impulse, TotalDeltaVIsTheSumOfNorms) {
  const std::vector<Impulse> impulses = {{0.0, {3e-3, 4e-3, 0.0}}, {10.0, {0.0, 0.0, -1e-3}}};
  EXPECT_NEAR(total_delta_v(impulses), 6e-3, 1e-18);  // 5 mm/s + 1 mm/s
}

TEST(Impulse, RejectsDecreasingTimes) {
  const auto r = validate_impulses({{10.0, {0, 0, 0}}, {5.0, {0, 0, 0}}}, 0.0, 100.0);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().field, "impulses[1].t");
}

TEST(Impulse, RejectsNonFiniteDeltaV) {
  const auto r = validate_impulses({{1.0, {NAN, 0, 0}}}, 0.0, 100.0);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().field, "impulses[0].dv_rtn");
}

}  // namespace
}  // namespace visors::control
