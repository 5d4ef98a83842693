// Passive-safety configuration: mission defaults and validation.
#include <gtest/gtest.h>

#include "visors/safety/passive_safety_settings.hpp"

namespace visors::safety {
namespace {

// Mission paper (Guffanti et al. 2023), science mode: 1.5 orbits, 3 sigma, 5 m, RN plane, 10 s.
TEST(PassiveSafetySettings, DefaultsAreTheMissionValues) {
  const PassiveSafetySettings s;
  EXPECT_EQ(s.epsilon_m, 5.0);
  EXPECT_EQ(s.horizon_orbits, 1.5);
  EXPECT_EQ(s.q_sigma, 3.0);
  EXPECT_EQ(s.plane, SafetyPlane::kRadialNormal);
  EXPECT_EQ(s.check_period_s, 10.0);
}

TEST(PassiveSafetySettings, RejectsANegativeEpsilon) {
  PassiveSafetySettings s;
  s.epsilon_m = -1.0;
  EXPECT_EQ(validate(s).error().field, "epsilon_m");
}

}  // namespace
}  // namespace visors::safety
