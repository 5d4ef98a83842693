// Cost of the time and frame conversions used at every filter / propagator step.
#include <benchmark/benchmark.h>

#include "visors/core/constants.hpp"
#include "visors/core/earth_frames.hpp"
#include "visors/core/gps_time.hpp"

namespace {

using visors::core::EarthOrientation;
using visors::core::GpsTime;
using visors::core::StateVector;

GpsTime mission_epoch() {
  return *GpsTime::parse("2024-10-01T00:00:00", visors::core::TimeScale::kGps);
}

EarthOrientation mission_eop() {
  EarthOrientation eop;
  eop.xp = 0.226101 * visors::core::kArcsecToRad;
  eop.yp = 0.407871 * visors::core::kArcsecToRad;
  eop.dut1 = 0.0590197;
  eop.lod = 0.0313e-3;
  return eop;
}

const StateVector kLeo{{6878137.0, 1000.0, -2000.0}, {10.0, -1020.0, 7540.0}};

// Full IAU 2006/2000A state transform (eraXys06a dominates: ~1300 nutation terms).
void BM_FullGcrfToItrfState(benchmark::State& state) {
  GpsTime t = mission_epoch();
  const EarthOrientation eop = mission_eop();
  for (auto _ : state) {
    benchmark::DoNotOptimize(visors::core::gcrf_to_itrf(t, kLeo, eop));
    t += 1.0;
  }
}
BENCHMARK(BM_FullGcrfToItrfState);

// On-board variant at a 1 Hz call rate (precession-nutation refreshed every 600 calls).
void BM_OnboardGcrfToItrfState(benchmark::State& state) {
  GpsTime t = mission_epoch();
  visors::core::OnboardEarthFrame frame(mission_eop());
  for (auto _ : state) {
    benchmark::DoNotOptimize(frame.gcrf_to_itrf(t, kLeo));
    t += 1.0;
  }
}
BENCHMARK(BM_OnboardGcrfToItrfState);

// On-board variant refreshing at every call: the cost of one IAU 2000B refresh.
void BM_OnboardGcrfToItrfStateRefreshEveryCall(benchmark::State& state) {
  GpsTime t = mission_epoch();
  visors::core::OnboardEarthFrame frame(mission_eop(), 0.0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(frame.gcrf_to_itrf(t, kLeo));
    t += 1.0;
  }
}
BENCHMARK(BM_OnboardGcrfToItrfStateRefreshEveryCall);

// GpsTime -> UTC calendar (leap-second lookup through eraDat).
void BM_GpsTimeToUtcCalendar(benchmark::State& state) {
  GpsTime t = mission_epoch();
  for (auto _ : state) {
    benchmark::DoNotOptimize(t.calendar(visors::core::TimeScale::kUtc));
    t += 1.0;
  }
}
BENCHMARK(BM_GpsTimeToUtcCalendar);

// GpsTime -> two-part UT1 Julian date (what the frame transforms need).
void BM_GpsTimeToUt1JulianDate(benchmark::State& state) {
  GpsTime t = mission_epoch();
  for (auto _ : state) {
    benchmark::DoNotOptimize(t.jd_ut1(0.0590197));
    t += 1.0;
  }
}
BENCHMARK(BM_GpsTimeToUt1JulianDate);

}  // namespace
