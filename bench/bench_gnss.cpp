// GPS models: satellite state from a broadcast ephemeris (IS-GPS-200 with analytic velocity), and
// one receiver epoch for both spacecraft (visibility of 31 satellites, light time, channels,
// observables). Data: the 2024 NYA1 navigation file moved to 2024-10-01 (data/ via
// VISORS_DATA_PATH).
#include <benchmark/benchmark.h>

#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/klobuchar.hpp"
#include "sim/gps_test_world.hpp"

namespace {

using namespace visors;

void BM_BroadcastState(benchmark::State& state) {
  const gnss::GpsConstellation constellation = test::mission_constellation();
  const gnss::BroadcastEphemeris& eph = constellation.satellites().front();
  core::GpsTime t = eph.toe;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gnss::broadcast_state(eph, t));
    t += std::chrono::nanoseconds(1'000'000);
  }
}
BENCHMARK(BM_BroadcastState);

void BM_KlobucharTopside(benchmark::State& state) {
  const gnss::KlobucharCoefficients c = test::nya_klobuchar();
  double az = 0.0;
  for (auto _ : state) {
    az += 0.001;
    benchmark::DoNotOptimize(gnss::klobuchar_topside_delay_m(c, {0.7, 0.3, az, 0.5}, 500e3, test::kMissionEpoch));
  }
}
BENCHMARK(BM_KlobucharTopside);

// Both spacecraft's receivers at one epoch (40 m apart), 1 Hz along the orbit.
void BM_ReceiverEpochTwoSpacecraft(benchmark::State& state) {
  const gnss::GpsConstellation constellation = test::mission_constellation();
  const auto satellites = sim::GpsSatelliteTruth::create(constellation, {}, sim::RandomStream(1, "gps")).value();
  sim::GpsReceiverSettings settings;
  settings.klobuchar = test::nya_klobuchar();
  auto chief = sim::GpsReceiver::create(settings, sim::RandomStream(1, "dsc")).value();
  auto deputy = sim::GpsReceiver::create(settings, sim::RandomStream(1, "osc")).value();
  test::CircularOrbit chief_orbit, deputy_orbit;
  deputy_orbit.along_offset_m = 40.0;
  double t = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    const auto chief_pose = test::pose(chief_orbit, t);
    const auto deputy_pose = test::pose(deputy_orbit, t);
    t += 1.0;
    state.ResumeTiming();
    benchmark::DoNotOptimize(chief.measure(chief_pose, satellites));
    benchmark::DoNotOptimize(deputy.measure(deputy_pose, satellites));
  }
}
BENCHMARK(BM_ReceiverEpochTwoSpacecraft)->Unit(benchmark::kMicrosecond);

}  // namespace
