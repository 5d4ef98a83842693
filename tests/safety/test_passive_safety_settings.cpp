// Passive-safety configuration: mission defaults and validation.
#include <gtest/gtest.h>

#include "visors/safety/passive_safety_settings.hpp"

namespace visors::safety {
namespace {

// Guffanti et al., AAS 23-149, 2023, Tables 3 and 5, science mode: 3 sigma, 5 m, RN plane, 10 s;
// the horizon default is 1.5 chief orbits (the paper's Table 5 lists 1.5 h;
// docs/algorithms/safety.md#mission-settings).
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
