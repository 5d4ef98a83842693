// The filter's state layout (Guffanti et al., AAS 23-149, 2023, sec. 4.2, eq. (1): 13 + 13 + 24 +
// 24 = 74, plus the 24 SD multipath states of nav/sd_multipath.hpp: 98) and its units.
#include <gtest/gtest.h>

#include "visors/nav/navigation_state.hpp"

namespace visors::nav {
namespace {

TEST(NavigationState, HasSeventyFourStatesPlusTheMultipathBank) { EXPECT_EQ(kNavStates, 74 + 24); }

TEST(NavigationState, OscBlockFollowsTheDscBlock) { EXPECT_EQ(state::position(Craft::kOsc), 13); }

TEST(NavigationState, MultipathBankFollowsTheSdcpBank) { EXPECT_EQ(state::kSdcpAmbiguities + kGpsSlots, state::kSdMultipath); }

TEST(NavigationState, MultipathBankIsLast) { EXPECT_EQ(state::kSdMultipath + kGpsSlots, kNavStates); }

TEST(NavigationState, MultipathInMillimetres) { EXPECT_EQ(unit(state::kSdMultipath + 5), 1e-3); }

TEST(NavigationState, VelocityInMillimetresPerSecond) { EXPECT_EQ(unit(state::velocity(Craft::kOsc) + 2), 1e-3); }

TEST(NavigationState, EmpiricalAccelerationInMicrometresPerSecondSquared) {
  EXPECT_EQ(unit(state::empirical_acceleration(Craft::kDsc)), 1e-6);
}

TEST(NavigationState, PhaseCentreInMillimetres) { EXPECT_EQ(unit(state::phase_center(Craft::kOsc) + 1), 1e-3); }

TEST(NavigationState, ClockAndAmbiguitiesUnscaled) {
  EXPECT_EQ(unit(state::clock(Craft::kOsc)) + unit(state::kGraphicAmbiguities) + unit(state::kSdMultipath - 1), 3.0);
}

}  // namespace
}  // namespace visors::nav
