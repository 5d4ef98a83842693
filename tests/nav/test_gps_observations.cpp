// The filter's input checks (nav/gps_observations.hpp): structural errors refuse the epoch and
// name the field; implausible values only skip the observation.
#include <gtest/gtest.h>

#include <string_view>

#include <cmath>

#include "visors/nav/gps_observations.hpp"

namespace visors::nav {
namespace {

GpsReceiverEpoch two_satellites() {
  GpsReceiverEpoch e;
  e.count = 2;
  e.observations[0] = {5, 2.1e7, 1.1e8, false};
  e.observations[1] = {9, 2.4e7, 1.3e8, true};
  return e;
}

TEST(GpsObservations, AcceptsAValidEpoch) { EXPECT_TRUE(check(two_satellites()).ok()); }

TEST(GpsObservations, NamesAnInvalidPrn) {
  GpsReceiverEpoch e = two_satellites();
  e.observations[1].prn = 33;
  EXPECT_EQ(std::string_view(check(e).field()), "observations.prn");
}

TEST(GpsObservations, NamesARepeatedPrn) {
  GpsReceiverEpoch e = two_satellites();
  e.observations[1].prn = 5;
  EXPECT_EQ(check(e).problem(), core::Problem::kRepeated);
}

TEST(GpsObservations, RefusesACountBeyondTheSlots) {
  GpsReceiverEpoch e = two_satellites();
  e.count = kGpsSlots + 1;
  EXPECT_EQ(std::string_view(check(e).field()), "count");
}

TEST(GpsObservations, FindsByPrn) { EXPECT_EQ(two_satellites().find(9)->code_m, 2.4e7); }

TEST(GpsObservations, FindsNothingForAnAbsentPrn) { EXPECT_EQ(two_satellites().find(7), nullptr); }

// 1.9e7 m: a satellite at the zenith of a 500 km orbit (1.97e7 m) with a 2.3 ms clock offset
// (seen in the gnss-sim navigation file) is plausible.
TEST(GpsObservations, ZenithSatelliteWithALargeClockOffsetIsPlausible) {
  EXPECT_TRUE(plausible({21, 1.8999871e7, 9.98e7, false}));
}

TEST(GpsObservations, CodeOfAGroundReceiverIsNotPlausible) { EXPECT_FALSE(plausible({21, 1.2e7, 6e7, false})); }

TEST(GpsObservations, NonFinitePhaseIsNotPlausible) { EXPECT_FALSE(plausible({21, 2.2e7, NAN, false})); }

TEST(GpsObservations, NonFiniteCodeIsNotPlausible) { EXPECT_FALSE(plausible({21, NAN, 1e8, false})); }

}  // namespace
}  // namespace visors::nav
