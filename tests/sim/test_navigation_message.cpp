// The navigation message's timing (sim/navigation_message.hpp), from the frame structure of
// IS-GPS-200 sec. 20.3.2 worked by hand: subframe j of frame k spans [30 k + 6 (j - 1), 30 k + 6 j).
#include <gtest/gtest.h>

#include "sim/navigation_message.hpp"

namespace {

using visors::sim::ephemeris_decoded_at;

TEST(NavigationMessage, FromAFrameStartTakesEighteenSeconds) {
  EXPECT_DOUBLE_EQ(ephemeris_decoded_at(3000.0), 3018.0);  // subframes 1-3 of that frame
}

TEST(NavigationMessage, JustAfterAFrameStartTakesThirtySixSeconds) {
  // Subframes 2 and 3 of this frame (6-18 s), subframe 1 of the next (30-36 s).
  EXPECT_DOUBLE_EQ(ephemeris_decoded_at(3000.5), 3036.0);
}

TEST(NavigationMessage, FromSubframeFourTakesThirtySeconds) {
  EXPECT_DOUBLE_EQ(ephemeris_decoded_at(3018.0), 3048.0);  // subframes 1-3 of the next frame
}

TEST(NavigationMessage, InsideSubframeThreeWaitsForTheNextOne) {
  // From 3012.5: subframe 1 at 3030-3036, 2 at 3036-3042, 3 at 3042-3048.
  EXPECT_DOUBLE_EQ(ephemeris_decoded_at(3012.5), 3048.0);
}

TEST(NavigationMessage, NeverBeforeEighteenSeconds) {
  for (double a = 0.0; a < 60.0; a += 0.25) EXPECT_GE(ephemeris_decoded_at(a) - a, 18.0) << a;
}

}  // namespace
