// The receiver's epoch allocates nothing (its state is preallocated at creation). Kept apart
// from the other receiver tests: the allocation counter may be defined in one file only, and
// GCC 12 reports a false -Wmismatched-new-delete where std::map nodes meet it in one file.
#include <gtest/gtest.h>

#include "gps_test_world.hpp"
#include "support/allocation_counter.hpp"

namespace visors::sim {
namespace {

TEST(GpsReceiverAlloc, MeasureAllocatesNothing) {
  if (!test::have_mission_nav()) GTEST_SKIP() << test::kMissionNavFile << " not found: set VISORS_DATA_PATH";
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
