// The navigation filter's epoch (benchmark of the flight step): CdgpsFilter::predict + update of one
// spacecraft's filter at 1 Hz on the synthetic constellation (tests/support/synthetic_gps.hpp:
// ~8-9 satellites in view of each receiver, 40 m apart), after a warm-up that fixes the integers,
// so each timed epoch does the time update of both spacecraft (RK4 under the on-board model,
// 8x8 embedded gravity here), ~9 GRAPHIC and ~9 SDCP scalar updates, slot management and the
// integer resolution with the fixed solution and hold. Counters: median_us and p999_us per epoch
// over the 600 timed epochs of one iteration. The replay's figures on gnss-sim data (20x20
// gravity, drag, SRP, Sun, Moon) are in the README (`visors nav`). Argument: 0, the phase-centre
// states held (consider states: no attitude turn here, so every fix takes the Joseph form of
// nav/fixed_solution.hpp), the default; 1, always estimated. The synthetic antenna's attitude
// is the identity, so the integer resolution's elevation mask (above its plane) is off.
// Run: ninja -C build visors_bench_nav && build/bench/visors_bench_nav

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <vector>

#include "visors/gnss/ephemeris_set.hpp"
#include "visors/nav/cdgps_filter.hpp"
#include "visors/nav/orbit_time_update.hpp"
#include "support/synthetic_gps.hpp"

namespace {

using namespace visors;

dynamics::ForceModel model() {
  dynamics::ForceModelData data;
  data.gravity_field = dynamics::embedded_gravity_field();
  return dynamics::ForceModel::create(dynamics::ForceModelConfig::gravity_only(8, 8), {}, std::move(data)).value();
}

struct Data {
  core::GpsTime t0 = core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kGps).value();
  std::vector<gnss::BroadcastEphemeris> records = test::synthetic_constellation(t0);
  gnss::EphemerisSet ephemerides = gnss::EphemerisSet::screen(records);
  std::vector<nav::GpsReceiverEpoch> dsc, osc;
  core::StateVector x_dsc, x_osc;

  Data() {
    core::OnboardEarthFrame frame;
    const double r = 6878137.0, v = std::sqrt(3.986004415e14 / r);
    x_dsc = {Eigen::Vector3d(r, 0, 0), Eigen::Vector3d(0, v * 0.13, v * 0.99)};
    x_osc = {x_dsc.r + Eigen::Vector3d(0, 0, 40), x_dsc.v};
    dynamics::ForceModel truth = model();
    std::vector<double> integers(33, 12345.0);
    std::mt19937_64 rng(9);
    core::StateVector a = x_dsc, b = x_osc;
    for (int n = 0; n < 700; ++n) {
      const core::GpsTime t = t0 + static_cast<double>(n);
      dsc.push_back(test::synthetic_observations(t, {a.r, a.v, 10.0, Eigen::Vector3d::Zero()}, records, frame, integers, 0.1, 0.2, 0.002, rng));
      osc.push_back(test::synthetic_observations(t, {b.r, b.v, -5.0, Eigen::Vector3d::Zero()}, records, frame, integers, 0.3, 0.2, 0.002, rng));
      a = nav::propagate_mean(truth, t, a, Eigen::Vector3d::Zero(), 600.0, 1.0, 1.0).x_gcrf;
      b = nav::propagate_mean(truth, t, b, Eigen::Vector3d::Zero(), 600.0, 1.0, 1.0).x_gcrf;
    }
  }
};

void BM_CdgpsFilterEpoch(benchmark::State& state) {
  static const Data data;
  core::OnboardEarthFrame frame;
  std::vector<double> per_epoch_us;
  for (auto _ : state) {
    state.PauseTiming();
    nav::CdgpsSettings settings;
    settings.phase_center_consider_between_turns = state.range(0) == 0;
    settings.min_fix_elevation_deg = 0.0;
    auto filter = nav::CdgpsFilter::create(settings, model(), model()).value();
    filter.initialise(data.t0, data.x_dsc, data.x_osc, 10.0, -5.0);
    for (int n = 0; n < 100; ++n) {  // warm-up: cold start to fixed
      filter.predict(data.t0 + static_cast<double>(n));
      filter.update({&data.dsc[static_cast<std::size_t>(n)], &data.osc[static_cast<std::size_t>(n)], {}, {}},
                    data.ephemerides, frame);
    }
    state.ResumeTiming();
    for (int n = 100; n < 700; ++n) {
      const auto t0 = std::chrono::steady_clock::now();
      filter.predict(data.t0 + static_cast<double>(n));
      const auto report = filter.update(
          {&data.dsc[static_cast<std::size_t>(n)], &data.osc[static_cast<std::size_t>(n)], {}, {}}, data.ephemerides, frame);
      benchmark::DoNotOptimize(report.fix_applied);
      per_epoch_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  std::sort(per_epoch_us.begin(), per_epoch_us.end());
  state.counters["median_us"] = per_epoch_us[per_epoch_us.size() / 2];
  state.counters["p999_us"] = per_epoch_us[static_cast<std::size_t>(0.999 * static_cast<double>(per_epoch_us.size()))];
}

BENCHMARK(BM_CdgpsFilterEpoch)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
