// Per-call time of the reachable-set planner (control/reachable_set_planner.hpp, default settings:
// 241 grid times, 28-constraint restricted dual) on the VISORS science reconfigurations, for
// horizons of 0.5 and 1 orbit of the mission chief. Cases cycle through standby -> science,
// science -> standby and a small science-orbit trim, each at 8 chief phases (M0 = 0, 45, ...,
// 315 deg). Counters: median_us, worst_us (per call), median_exchange_iterations, failures.
// Run: ninja -C build visors_bench_planners && build/bench/visors_bench_planners

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "control/reachable_set_planner.hpp"

namespace {

using visors::astro::KeplerianElements;
using visors::astro::RelativeOrbitalElements;
using visors::control::ReachableSetPlanner;

constexpr double kDeg = std::numbers::pi / 180.0;

struct Case {
  KeplerianElements chief;
  RelativeOrbitalElements roe0;
  RelativeOrbitalElements target;
};

RelativeOrbitalElements roe_m(double a, double da, double dl, double dex, double dey, double dix, double diy) {
  RelativeOrbitalElements r;
  r << da, dl, dex, dey, dix, diy;
  return r / a;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (int phase = 0; phase < 8; ++phase) {
    const KeplerianElements chief{6378136.3 + 500e3, 0.004, 97.8 * kDeg, 157.5 * kDeg, 90.0 * kDeg, 45.0 * kDeg * phase};
    const double a = chief.a;
    const RelativeOrbitalElements science = roe_m(a, -2.62, 45.21, -34.51, 4.78, -18.72, 2.72);
    const RelativeOrbitalElements standby = roe_m(a, 0, 0, 0, 200, 0, 200);
    out.push_back({chief, standby, science});
    out.push_back({chief, science, standby});
    out.push_back({chief, science, roe_m(a, -2.0, 44.0, -33.5, 5.5, -18.9, 2.5)});
  }
  return out;
}

void BM_ReachableSetPlan(benchmark::State& state) {
  const double orbits = static_cast<double>(state.range(0)) / 100.0;
  auto created = ReachableSetPlanner::create();
  if (!created.ok()) {
    state.SkipWithError(created.error().describe().c_str());
    return;
  }
  ReachableSetPlanner planner = std::move(created).value();
  const std::vector<Case> all = cases();
  const double a = all.front().chief.a;
  const double tf = orbits * 2.0 * std::numbers::pi * std::sqrt(a * a * a / planner.settings().gravity.mu);
  std::vector<double> times;
  std::vector<int> exchanges;
  int failures = 0;
  std::size_t next = 0;
  for (auto _ : state) {
    const Case& c = all[next];
    const auto t0 = std::chrono::steady_clock::now();
    const auto plan = planner.plan(c.chief, c.roe0, c.target, 0.0, tf);
    const auto t1 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(plan);
    times.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    exchanges.push_back(planner.stats().exchange_iterations);
    if (!plan.ok()) ++failures;
    next = (next + 1) % all.size();
  }
  std::sort(times.begin(), times.end());
  std::sort(exchanges.begin(), exchanges.end());
  state.counters["median_us"] = times[times.size() / 2];
  state.counters["worst_us"] = times.back();
  state.counters["median_exchange_iterations"] = exchanges[exchanges.size() / 2];
  state.counters["failures"] = failures;
}
// Argument: horizon in hundredths of an orbit.
BENCHMARK(BM_ReachableSetPlan)->Arg(50)->Arg(100)->Iterations(5 * 24)->Unit(benchmark::kMicrosecond);

}  // namespace
