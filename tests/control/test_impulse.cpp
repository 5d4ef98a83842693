// Impulse list helpers.
#include <gtest/gtest.h>

#include <cmath>

#include "visors/control/impulse.hpp"
#include "visors/control/impulse_effect.hpp"

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

// ROE beyond 1e-2 (tens of km) are outside the first-order model every planner uses.
TEST(Impulse, RoeOutsideTheLinearModelIsRejected) {
  astro::RelativeOrbitalElements roe = astro::RelativeOrbitalElements::Zero();
  roe[astro::roe::kDa] = 0.1;
  const auto r = validate_roe(roe, "roe_target");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().field, "roe_target");
}

TEST(Impulse, MissionScaleRoeIsAccepted) {
  astro::RelativeOrbitalElements roe = astro::RelativeOrbitalElements::Zero();
  roe[astro::roe::kDey] = 200.0 / 6878136.3;  // standby orbit
  EXPECT_TRUE(validate_roe(roe, "roe").ok());
}

}  // namespace
}  // namespace visors::control
