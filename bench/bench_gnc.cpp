// Per-step cost of the flight component (median and 99.9th percentile: the computing budget of
// docs/requirements.md#computing-budget) and the wall time of a shortened closed-loop campaign.
//   BM_FlightComponentStep/standby  one hour of 1 Hz steps in standby (estimate, safety check
//                                   every 10 s, station-keeping checks and plans)
//   BM_FlightComponentStep/science  from the science orbit guidance picks, in closed loop with the
//                                   analytic formation: start_science, one 1.6-orbit transfer
//                                   leg, science mode, the MPC, least squares every 45 s, the
//                                   last burn and the first observation (until the transfer back)
//   BM_Record*                      encode + decode of one binary record (gnc/channel_record.hpp)
// Each step benchmark reports median_us, p999_us and max_us over the steps. The full campaign is timed with
//   /usr/bin/time -v build/apps/visors run   (README "Performance").
// Run: ninja -C build visors_bench_gnc && build/bench/visors_bench_gnc

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "visors/gnc/channel_record.hpp"
#include "visors/gnc/flight_component.hpp"
#include "gnc/formation_harness.hpp"

namespace {

using namespace visors::gnc;

const visors::core::GpsTime kT0 = visors::core::GpsTime::from_seconds(1.4e9);

void report(benchmark::State& state, std::vector<double> us) {
  std::sort(us.begin(), us.end());
  state.counters["median_us"] = us[us.size() / 2];
  state.counters["p999_us"] = us[static_cast<std::size_t>(0.999 * static_cast<double>(us.size() - 1))];
  state.counters["max_us"] = us.back();
}

void BM_FlightComponentStep(benchmark::State& state) {
  const bool science = state.range(0) == 1;
  // Standby off its design by 15 m in de (station keeping plans); science: on the science orbit
  // guidance picks, so the transfer is one leg.
  ScienceSettings settings;
  settings.geometry.north = choose_north_pole(test::mission_chief(), kT0, settings, settings.geometry, {}).value();
  const auto first = next_observation(test::mission_chief(), kT0, 1, settings, {}).value();
  const Eigen::Matrix<double, 6, 1> roe =
      science ? Eigen::Matrix<double, 6, 1>(test::mission_chief().a * first.roe_target) : test::roe_m(0, 0, 0, 215, 0, 200);
  const int steps = science ? 30000 : 3600;
  std::vector<double> us;
  us.reserve(static_cast<std::size_t>(steps));
  for (auto _ : state) {
    test::FormationHarness harness(test::mission_chief(), roe, kT0);
    auto component = FlightComponent::create(GncConfig{}).value();
    bool observed = false;
    for (int k = 0; k < steps && !(observed && component.mode() == Mode::kTransferToStandby); ++k) {
      GncInputs in = harness.inputs(k);
      if (k == 0) in.command = GroundCommand{kT0, GroundCommand::Kind::kToStandby, 0};
      if (k == 1 && science) in.command = GroundCommand{kT0 + 1.0, GroundCommand::Kind::kStartScience, 1};
      const auto t0 = std::chrono::steady_clock::now();
      const GncOutputs out = component.step(in);
      us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
      if (out.maneuver) harness.apply_deputy_dv(k, out.maneuver->dv_body_mps);  // body = GCRF (identity attitude)
      observed = observed || out.mode == Mode::kScience;
    }
  }
  state.counters["steps"] = static_cast<double>(us.size());
  report(state, us);
}
BENCHMARK(BM_FlightComponentStep)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kMillisecond);

// Encode and decode of one record (gnc/channel_record.hpp): the navigation record (288 bytes,
// the largest) and the ground command (32 bytes), CRC-32C included.
template <class Message>
void codec_round_trip(benchmark::State& state, const Message& message) {
  RecordBuffer buffer{};
  Message out{};
  RecordHeader header;
  std::uint32_t sequence = 0;
  for (auto _ : state) {
    const std::size_t n = encode(message, ++sequence, buffer);
    benchmark::DoNotOptimize(decode(std::span(buffer).first(n), out, header));
    benchmark::DoNotOptimize(out);
  }
}

void BM_RecordNavigation(benchmark::State& state) {
  test::FormationHarness harness(test::mission_chief(), test::roe_m(0, 0, 0, 200, 0, 200), kT0);
  codec_round_trip(state, *harness.inputs(1.0).navigation);
}
BENCHMARK(BM_RecordNavigation);

void BM_RecordGroundCommand(benchmark::State& state) {
  codec_round_trip(state, GroundCommand{kT0, GroundCommand::Kind::kStartScience, 10});
}
BENCHMARK(BM_RecordGroundCommand);

// The largest records: a GPS message of 12 channels with a broadcast record (816 bytes) and a
// crosslink with its navigation part (480 bytes).
void BM_RecordGps(benchmark::State& state) {
  GpsMessage m;
  m.t = m.epoch.t = kT0;
  m.epoch.channel_count = visors::gnss::kMaxGpsChannels;
  for (int k = 0; k < m.epoch.channel_count; ++k) {
    auto& c = m.epoch.channels[static_cast<std::size_t>(k)];
    c.prn = k + 1;
    c.pseudorange_m = 2.1e7 + 1e5 * k;
    c.carrier_phase_cycles = 1.1e8 + 1e3 * k;
  }
  m.has_ephemeris = true;
  m.ephemeris.prn = 7;
  m.ephemeris.sqrt_a = 5153.6;
  codec_round_trip(state, m);
}
BENCHMARK(BM_RecordGps);

void BM_RecordCrosslink(benchmark::State& state) {
  CrosslinkMessage m;
  m.t = kT0;
  m.navigation.has_epoch = true;
  m.navigation.epoch.t = kT0;
  m.navigation.epoch.count = visors::gnss::kMaxGpsChannels;
  for (int k = 0; k < m.navigation.epoch.count; ++k) m.navigation.epoch.observations[static_cast<std::size_t>(k)].prn = k + 1;
  codec_round_trip(state, m);
}
BENCHMARK(BM_RecordCrosslink);

}  // namespace
