// The on-board store of decoded broadcast records against the ground's screened day
// (EphemerisSet) on brdc1820.10n (IGS, 2010-07-01), and its refusals.
#include <gtest/gtest.h>

#include <vector>

#include "visors/gnss/ephemeris_set.hpp"
#include "visors/gnss/ephemeris_store.hpp"
#include "visors/gnss/files/rinex_nav_file.hpp"
#include "gnss_test_data.hpp"

namespace visors::gnss {
namespace {

using Status = EphemerisStore::AcceptStatus;

class EphemerisStoreTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!test::have_gnss_data(test::kBrdc20100701)) return;
    auto file = files::read_rinex_navigation(test::gnss_data(test::kBrdc20100701));
    ASSERT_TRUE(file.ok()) << file.error().describe();
    nav_ = new files::NavigationFile(std::move(file).value());
  }
  static void TearDownTestSuite() { delete nav_; }
  void SetUp() override { VISORS_REQUIRE_GNSS_DATA(test::kBrdc20100701); }

  // A healthy record of PRN 12 (its first in the file).
  static BroadcastEphemeris healthy() {
    for (const auto& r : nav_->records) {
      if (r.prn == 12 && r.health == 0) return r;
    }
    ADD_FAILURE() << "no PRN 12 record";
    return {};
  }

  static files::NavigationFile* nav_;
};
files::NavigationFile* EphemerisStoreTest::nav_ = nullptr;

// What a receiver has decoded by each hour of the day (the records with t_oe up to then, in file
// order) selects the same record as the ground's screening of those records: the two latest per
// satellite are enough, and the store refuses what the screening marks unusable.
TEST_F(EphemerisStoreTest, SelectsAsTheScreenedDayDoes) {
  int compared = 0;
  for (int hour = 2; hour <= 22; hour += 2) {
    const core::GpsTime t = core::GpsTime::parse("2010-07-01T00:00:00", core::TimeScale::kGps).value() + 3600.0 * hour;
    std::vector<BroadcastEphemeris> decoded;
    EphemerisStore store;
    for (const auto& r : nav_->records) {
      if (r.toe > t) continue;
      decoded.push_back(r);
      store.accept(r);
    }
    const EphemerisSet set = EphemerisSet::screen(decoded);
    for (int prn = 1; prn <= kMaxGpsPrn; ++prn) {
      const BroadcastEphemeris* expected = set.select(prn, t + 900.0);
      const BroadcastEphemeris* got = store.select(prn, t + 900.0);
      ASSERT_EQ(expected == nullptr, got == nullptr) << "PRN " << prn << " at hour " << hour;
      if (expected == nullptr) continue;
      EXPECT_EQ(got->toe, expected->toe) << "PRN " << prn << " at hour " << hour;
      EXPECT_EQ(got->iode, expected->iode) << "PRN " << prn << " at hour " << hour;
      ++compared;
    }
  }
  EXPECT_GT(compared, 250);  // ~29 healthy satellites x 11 times
}

TEST_F(EphemerisStoreTest, KeepsTheTwoNewestRecordsPerSatellite) {
  EphemerisStore store;
  core::GpsTime newest;
  for (const auto& r : nav_->records) {
    if (r.prn != 12) continue;
    EXPECT_NE(store.accept(r), Status::kInconsistent);
    newest = std::max(newest, r.toe);
  }
  EXPECT_EQ(store.count(12), EphemerisStore::kRecordsPerPrn);
  EXPECT_EQ(store.satellites(), 1);
  ASSERT_NE(store.select(12, newest), nullptr);
  EXPECT_EQ(store.select(12, newest)->toe, newest);
}

TEST_F(EphemerisStoreTest, RefusesImplausibleRecords) {
  EphemerisStore store;
  BroadcastEphemeris bad = healthy();
  bad.sqrt_a = 0.0;
  EXPECT_EQ(store.accept(bad), Status::kImplausible);
  EXPECT_EQ(store.count(12), 0);
}

TEST_F(EphemerisStoreTest, NeverSelectsUnhealthyRecords) {
  EphemerisStore store;
  BroadcastEphemeris sick = healthy();
  sick.health = 63;  // as PRN 1 and 25 in this file
  EXPECT_EQ(store.accept(sick), Status::kUnhealthy);
  EXPECT_EQ(store.select(12, sick.toe), nullptr);
}

// The file's corrupt PRN 1 record (t_oe 06:00, health 0, ~40,755 km off: the screening test of
// test_broadcast_ephemeris.cpp) arrives after an unhealthy but plausible record of the same
// satellite: that neighbour is enough to refuse it.
TEST_F(EphemerisStoreTest, RefusesTheFilesCorruptRecordAgainstItsUnhealthyNeighbour) {
  EphemerisStore store;
  Status corrupt = Status::kStored;
  for (const auto& r : nav_->records) {
    if (r.prn != 1) continue;
    const Status s = store.accept(r);
    if (r.health == 0) corrupt = s;
  }
  EXPECT_EQ(corrupt, Status::kInconsistent);
}

TEST_F(EphemerisStoreTest, RefusesRepeatsOfTheBroadcast) {
  EphemerisStore store;
  ASSERT_EQ(store.accept(healthy()), Status::kStored);
  EXPECT_EQ(store.accept(healthy()), Status::kDuplicate);
  EXPECT_EQ(store.count(12), 1);
}

TEST_F(EphemerisStoreTest, RefusesARecordOlderThanBothStoredOnes) {
  std::vector<BroadcastEphemeris> prn12;
  for (const auto& r : nav_->records) {
    if (r.prn == 12 && r.health == 0) prn12.push_back(r);
  }
  ASSERT_GE(prn12.size(), 3u);
  EphemerisStore store;
  ASSERT_EQ(store.accept(prn12[1]), Status::kStored);
  ASSERT_EQ(store.accept(prn12[2]), Status::kStored);
  EXPECT_EQ(store.accept(prn12[0]), Status::kStale);
}

// A record carrying another orbit (mean anomaly 0.5 rad off: ~13,000 km along the orbit, like
// the file's corrupt PRN 1 record at 40,000 km) is refused beside a good neighbour, and the good
// one stays in use.
TEST_F(EphemerisStoreTest, RefusesARecordThatDisagreesWithItsNeighbour) {
  EphemerisStore store;
  const BroadcastEphemeris good = healthy();
  ASSERT_EQ(store.accept(good), Status::kStored);
  BroadcastEphemeris corrupt = good;
  corrupt.toe = good.toe + 7200.0;
  corrupt.toc = good.toc + 7200.0;
  corrupt.iode = good.iode + 1;
  corrupt.m0_rad += 0.5;
  EXPECT_EQ(store.accept(corrupt), Status::kInconsistent);
  ASSERT_NE(store.select(12, good.toe), nullptr);
  EXPECT_EQ(store.select(12, good.toe)->iode, good.iode);
}

TEST_F(EphemerisStoreTest, SelectsNothingOutsideTheFitIntervalOrForABadPrn) {
  EphemerisStore store;
  const BroadcastEphemeris r = healthy();
  ASSERT_EQ(store.accept(r), Status::kStored);
  EXPECT_EQ(store.select(12, r.toe + 0.5 * r.fit_interval_h * 3600.0 + 1.0), nullptr);
  EXPECT_EQ(store.select(0, r.toe), nullptr);
  EXPECT_EQ(store.select(33, r.toe), nullptr);
  EXPECT_EQ(store.count(40), 0);
}

}  // namespace
}  // namespace visors::gnss
