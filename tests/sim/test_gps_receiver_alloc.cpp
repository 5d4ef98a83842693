// The receiver's epoch allocates nothing (its state is preallocated at creation). Kept apart
// from the other receiver tests: the allocation counter may be defined in one file only, and
// GCC 12 reports a false -Wmismatched-new-delete where std::map nodes meet it in one file.
#include <gtest/gtest.h>

#include "gps_test_world.hpp"
#include "support/allocation_counter.hpp"

namespace visors::sim {
namespace {

TEST(GpsReceiverAlloc, MeasureAllocatesNothing) {
  if (!test::have_mission_nav()) GTEST_FAIL() << test::kMissionNavFile << " not found: set VISORS_DATA_PATH";
  const gnss::GpsConstellation constellation = test::mission_constellation();
  const auto truth = GpsSatelliteTruth::create(constellation, {}, RandomStream(7, "gps.satellites")).value();
  GpsReceiverSettings settings;
  settings.klobuchar = test::nya_klobuchar();
  settings.cycle_slip_probability = 0.01;
  GpsReceiver receiver = GpsReceiver::create(settings, RandomStream(3, "alloc")).value();
  receiver.measure(test::pose(test::CircularOrbit{}, 0.0), truth);
  const long allocations = test::count_allocations([&] {
    for (int step = 1; step < 50; ++step) receiver.measure(test::pose(test::CircularOrbit{}, step, 0.02 * step), truth);
  });
  EXPECT_EQ(allocations, 0);
}

}  // namespace
}  // namespace visors::sim

#include "visors/gnc/channel_record.hpp"
#include "visors/sim/navigation_setup.hpp"

namespace visors::sim {
namespace {

// The flight rule for the on-board navigation (gnc/onboard_navigation.hpp): once started, a step
// (the own epoch, the other's over the crosslink, the joint epoch's filter update, the solution,
// its navigation telemetry record) allocates nothing, counted at malloc. The two receivers fly
// 40 m apart on the test world's circular orbit; the broadcast records are loaded before the
// counted steps.
TEST(OnboardNavigationAlloc, StepAllocatesNothing) {
  if (!test::have_mission_nav()) GTEST_FAIL() << test::kMissionNavFile << " not found: set VISORS_DATA_PATH";
  const gnss::GpsConstellation constellation = test::mission_constellation();
  const auto truth = GpsSatelliteTruth::create(constellation, {}, RandomStream(7, "gps.satellites")).value();
  GpsReceiverSettings settings;
  settings.klobuchar = test::nya_klobuchar();
  GpsReceiver dsc_rx = GpsReceiver::create(settings, RandomStream(3, "dsc")).value();
  GpsReceiver osc_rx = GpsReceiver::create(settings, RandomStream(4, "osc")).value();
  test::CircularOrbit dsc_orbit, osc_orbit;
  osc_orbit.along_offset_m = 40.0;
  auto made = make_onboard_navigation(default_campaign(), gnc::Spacecraft::kDsc);
  ASSERT_TRUE(made.ok()) << made.error().describe();
  gnc::OnboardNavigation nav = std::move(made).value();
  for (const auto& record : truth.broadcast()) nav.add_ephemeris(record);
  const auto step = [&](int k) {
    const ReceiverPose pd = test::pose(dsc_orbit, k), po = test::pose(osc_orbit, k);
    const nav::GpsReceiverEpoch own = nav::receiver_epoch(dsc_rx.measure(pd, truth).measurement);
    gnc::CrosslinkNavigation peer;
    peer.has_epoch = true;
    peer.epoch = gnc::crosslink_epoch(nav::receiver_epoch(osc_rx.measure(po, truth).measurement));
    nav.add_own_epoch(own, Eigen::Quaterniond::Identity());
    nav.add_peer(peer);
    (void)nav.solve(own.t + 1.0);
    gnc::RecordBuffer record{};
    (void)gnc::encode(nav.telemetry(own.t + 1.0), 0, record);  // its telemetry record too
  };
  for (int k = 0; k < 30; ++k) step(k);  // the cold start and the first updates
  ASSERT_TRUE(nav.initialised());
  const long allocations = test::count_allocations([&] {
    for (int k = 30; k < 60; ++k) step(k);
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(nav.counters().epochs_joint, 20);
}

}  // namespace
}  // namespace visors::sim
