#include <gtest/gtest.h>

#include "visors/core/angles.hpp"
#include "visors/core/constants.hpp"

namespace {
using visors::core::kPi;

// Reference: the (-pi, pi] convention of docs/conventions.md for dlambda.
TEST(WrapPi, PiStaysPi) { EXPECT_DOUBLE_EQ(visors::core::wrap_pi(kPi), kPi); }
TEST(WrapPi, MinusPiBecomesPi) { EXPECT_DOUBLE_EQ(visors::core::wrap_pi(-kPi), kPi); }
TEST(WrapPi, ThreeHalfPiIsMinusHalfPi) {
  // round-off: one reduction by 2 pi (ulp(pi) = 4.4e-16); measured 0 (2026-11)
  EXPECT_NEAR(visors::core::wrap_pi(1.5 * kPi), -0.5 * kPi, 1e-15);
}
TEST(WrapPi, LargeMultipleKeepsRemainder) {
  // round-off: reducing ~628 rad (ulp 1.1e-13); measured 1.8e-14 (2026-11)
  EXPECT_NEAR(visors::core::wrap_pi(0.25 + 200.0 * kPi), 0.25, 1e-12);
}
TEST(WrapTwoPi, NegativeSmallAngle) {
  // round-off: one addition of 2 pi (ulp 8.9e-16); measured 0 (2026-11)
  EXPECT_NEAR(visors::core::wrap_two_pi(-0.5), 2.0 * kPi - 0.5, 1e-15);
}
TEST(WrapTwoPi, NeverReturnsTwoPi) {
  EXPECT_LT(visors::core::wrap_two_pi(-1e-18), 2.0 * kPi);
}
}  // namespace
