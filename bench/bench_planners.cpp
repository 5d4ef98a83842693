// Per-call time of the planners, the buffer and the safety checks on the VISORS reconfigurations:
// standby -> science, science -> standby and a small science-orbit trim, each at 8 chief phases
// (M0 = 0, 45, ..., 315 deg). Reachable set (default settings: 241 grid times, 28-constraint
// restricted dual) for horizons of 0.5 and 1 orbit; closed form over 2 orbits; least squares at 3
// fixed times over 0.6 orbit; one passive-safety check over 1.5 orbits (RN plane, 3 sigma, the
// default 120 samples per orbit); the escape; the buffer of a 55 mm/s impulse.
// Counters: median_us, worst_us (per call), failures.
// Run: ninja -C build visors_bench_planners && build/bench/visors_bench_planners

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "visors/control/closed_form_planner.hpp"
#include "visors/control/least_squares_planner.hpp"
#include "visors/control/maneuver_buffer.hpp"
#include "visors/control/reachable_set_planner.hpp"
#include "visors/safety/escape_maneuver.hpp"
#include "visors/safety/passive_safety.hpp"

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

// Times `call(case)` over the cases, cyclically; per-call median and worst.
template <typename Call>
void time_cases(benchmark::State& state, Call call) {
  const std::vector<Case> all = cases();
  std::vector<double> times;
  int failures = 0;
  std::size_t next = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = call(all[next]);
    const auto t1 = std::chrono::steady_clock::now();
    times.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    if (!ok) ++failures;
    next = (next + 1) % all.size();
  }
  std::sort(times.begin(), times.end());
  state.counters["median_us"] = times[times.size() / 2];
  state.counters["worst_us"] = times.back();
  state.counters["failures"] = failures;
}

double orbit_period(const KeplerianElements& chief) {
  return 2.0 * std::numbers::pi * std::sqrt(chief.a * chief.a * chief.a / 3.986004415e14);
}

void BM_ClosedFormPlan(benchmark::State& state) {
  time_cases(state, [](const Case& c) {
    const auto plan = visors::control::plan_closed_form(c.chief, c.roe0, c.target, 2.0 * orbit_period(c.chief));
    benchmark::DoNotOptimize(plan);
    return plan.ok();
  });
}
BENCHMARK(BM_ClosedFormPlan)->Iterations(5 * 24)->Unit(benchmark::kMicrosecond);

void BM_LeastSquaresPlan(benchmark::State& state) {
  time_cases(state, [](const Case& c) {
    const double period = orbit_period(c.chief);
    const double times[] = {0.05 * period, 0.3 * period, 0.55 * period};
    const auto plan = visors::control::plan_least_squares(c.chief, c.roe0, c.target, 0.6 * period, times);
    benchmark::DoNotOptimize(plan);
    return plan.ok();
  });
}
BENCHMARK(BM_LeastSquaresPlan)->Iterations(5 * 24)->Unit(benchmark::kMicrosecond);

// Navigation-level covariance: (5 cm)^2 per a*dROE component.
Eigen::Matrix<double, 6, 6> nav_covariance(double a) {
  return Eigen::Matrix<double, 6, 6>::Identity() * (0.05 * 0.05) / (a * a);
}

void BM_PassiveSafetyCheck(benchmark::State& state) {
  const visors::safety::PassiveSafetySettings settings;
  time_cases(state, [&](const Case& c) {
    const auto r = visors::safety::evaluate_passive_safety(c.chief, c.target, nav_covariance(c.chief.a), settings);
    benchmark::DoNotOptimize(r);
    return r.ok();
  });
}
BENCHMARK(BM_PassiveSafetyCheck)->Iterations(5 * 24)->Unit(benchmark::kMicrosecond);

void BM_EscapePlan(benchmark::State& state) {
  time_cases(state, [](const Case& c) {
    const auto r = visors::safety::plan_escape(c.chief, c.target, nav_covariance(c.chief.a), 0.0, {});
    benchmark::DoNotOptimize(r);
    return r.ok();
  });
}
BENCHMARK(BM_EscapePlan)->Iterations(5 * 24)->Unit(benchmark::kMicrosecond);

void BM_BufferImpulse(benchmark::State& state) {
  time_cases(state, [](const Case& c) {
    const auto r = visors::control::buffer_impulse(c.chief, {2000.0, {0.010, 0.050, 0.020}}, 10.62);
    benchmark::DoNotOptimize(r);
    return r.ok();
  });
}
BENCHMARK(BM_BufferImpulse)->Iterations(5 * 24)->Unit(benchmark::kMicrosecond);

}  // namespace
