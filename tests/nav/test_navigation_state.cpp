// The filter's state layout (navigation digest sec. 5.1: 13 + 13 + 24 + 24 = 74) and its units.
#include <gtest/gtest.h>

#include "nav/navigation_state.hpp"

namespace visors::nav {
namespace {

TEST(NavigationState, HasTheDigestsSeventyFourStates) { EXPECT_EQ(kNavStates, 74); }

TEST(NavigationState, OscBlockFollowsTheDscBlock) { EXPECT_EQ(state::position(Craft::kOsc), 13); }

TEST(NavigationState, SdcpBankIsLast) { EXPECT_EQ(state::kSdcpAmbiguities + kGpsSlots, kNavStates); }

TEST(NavigationState, VelocityInMillimetresPerSecond) { EXPECT_EQ(unit(state::velocity(Craft::kOsc) + 2), 1e-3); }

TEST(NavigationState, EmpiricalAccelerationInMicrometresPerSecondSquared) {
  EXPECT_EQ(unit(state::empirical_acceleration(Craft::kDsc)), 1e-6);
}

TEST(NavigationState, PhaseCentreInMillimetres) { EXPECT_EQ(unit(state::phase_center(Craft::kOsc) + 1), 1e-3); }

TEST(NavigationState, ClockAndAmbiguitiesUnscaled) {
  EXPECT_EQ(unit(state::clock(Craft::kOsc)) + unit(state::kGraphicAmbiguities) + unit(kNavStates - 1), 3.0);
}

}  // namespace
}  // namespace visors::nav
