// The navigation message's timing (sim/navigation_message.hpp), from the frame structure of
// IS-GPS-200 sec. 20.3.2 worked by hand: subframe j of frame k spans [30 k + 6 (j - 1), 30 k + 6 j);
// and which data set a receiver passes on when (the rule `visors run` and `visors gnss-sim` share).
#include <gtest/gtest.h>

#include <optional>
#include <utility>
#include <vector>

#include "visors/sim/navigation_message.hpp"

namespace {

using visors::sim::ephemeris_decoded_at;
using visors::sim::newly_decoded_data_set;

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

// Two data sets of G05 (t_oe t0 and t0 + 2 h) and one of G07, in the simulator's order (the first
// sets, then the refresh); t0 at a frame start (a multiple of 30 s of GPS time).
struct DataSets {
  visors::core::GpsTime t0 = visors::core::GpsTime::from_seconds(1'000'020'000.0);
  std::vector<visors::gnss::BroadcastEphemeris> records;
  visors::sim::DataSetsByPrn by_prn;
  static constexpr double kHalfRefreshS = 3600.0;
  DataSets() {
    for (const auto& [prn, toe_s] : {std::pair{5, 0.0}, {7, 0.0}, {5, 7200.0}}) {
      visors::gnss::BroadcastEphemeris e;
      e.prn = prn;
      e.toe = t0 + toe_s;
      records.push_back(e);
    }
    by_prn = visors::sim::data_sets_by_prn(records);
  }
  // The set of G05 passed on at t0 + t_s by a receiver locked for lock_s, `next` as the caller keeps it.
  [[nodiscard]] std::optional<std::size_t> g05(double t_s, double lock_s, std::size_t next) const {
    return newly_decoded_data_set(records, by_prn[5], t0 + t_s, kHalfRefreshS, lock_s, next);
  }
};

TEST(DataSets, ArePerPrnInTheirBroadcastOrder) {
  const DataSets d;
  EXPECT_EQ(d.by_prn[5], (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(d.by_prn[7], (std::vector<std::size_t>{1}));
  EXPECT_TRUE(d.by_prn[6].empty());
}

// Locked at t0 (a frame start): the first set 18 s later, not a second before; then never again.
TEST(DataSets, TheFirstSetIsPassedOnEighteenSecondsAfterALockAtAFrameStart) {
  const DataSets d;
  EXPECT_FALSE(d.g05(17.0, 17.0, 0).has_value());
  EXPECT_EQ(d.g05(18.0, 18.0, 0), 0u);
  EXPECT_FALSE(d.g05(100.0, 100.0, 1).has_value());  // passed on already
}

// Tracked throughout: the second set is in force from its t_oe - 1 h (t0 + 3600 s, a frame start)
// and decoded 18 s later.
TEST(DataSets, TheNextSetIsDecodedFromItsFirstBroadcast) {
  const DataSets d;
  EXPECT_FALSE(d.g05(3599.0, 3599.0, 1).has_value());  // the first set still in force
  EXPECT_FALSE(d.g05(3617.0, 3617.0, 1).has_value());
  EXPECT_EQ(d.g05(3618.0, 3618.0, 1), 1u);
}

// A lock after the switch: the set in force then, decoded after the lock (from 3660.5 s, just
// after a frame start: subframe 1 at 3690-3696, 2 at 3666-3672, 3 at 3672-3678); the first set is
// never passed on.
TEST(DataSets, ALockAfterTheSwitchGetsTheSetInForce) {
  const DataSets d;
  EXPECT_FALSE(d.g05(3695.5, 35.0, 0).has_value());
  EXPECT_EQ(d.g05(3696.0, 35.5, 0), 1u);
}

// Lost and re-acquired before it was decoded: the wait starts again from the new lock.
TEST(DataSets, ANewLockRestartsTheWait) {
  const DataSets d;
  // Locked at 15 s (the first lock's progress is lost): subframe 1 at 30-36, 2 at 36-42, 3 at 42-48.
  EXPECT_FALSE(d.g05(20.0, 5.0, 0).has_value());
  EXPECT_FALSE(d.g05(47.0, 32.0, 0).has_value());
  EXPECT_EQ(d.g05(48.0, 33.0, 0), 0u);
}

// refresh_s = 0 (one set for the whole run): the first set for ever.
TEST(DataSets, WithoutRefreshTheFirstSetStays) {
  const DataSets d;
  EXPECT_EQ(newly_decoded_data_set(d.records, d.by_prn[5], d.t0 + 7200.0, 0.0, 7200.0, 0), 0u);
  EXPECT_FALSE(newly_decoded_data_set(d.records, d.by_prn[5], d.t0 + 7300.0, 0.0, 7300.0, 1).has_value());
}

TEST(DataSets, ASatelliteWithoutSetsHasNone) {
  const DataSets d;
  EXPECT_FALSE(newly_decoded_data_set(d.records, d.by_prn[6], d.t0 + 100.0, DataSets::kHalfRefreshS, 100.0, 0).has_value());
}

}  // namespace
