// Cost of the astro building blocks used in the GNC loop (ns per call).
#include <benchmark/benchmark.h>

#include "visors/astro/control_input_matrix.hpp"
#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/mean_osculating.hpp"
#include "visors/astro/roe_rtn_map.hpp"
#include "visors/astro/roe_stm.hpp"
#include "visors/core/constants.hpp"

namespace {
using namespace visors::astro;

const visors::core::EarthGravityConstants kGravity;
// VISORS chief (docs/conventions.md), argp 90 deg, M 60 deg.
const KeplerianElements kChief{6878136.3, 0.004, 1.7069320084504542, 2.748893571891069,
                               1.5707963267948966, 1.0471975511965976};

void BM_J2RoeStm(benchmark::State& state) {
  double tau = 5677.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tau);
    RoeStm phi = j2_roe_stm(kChief, tau, kGravity);
    benchmark::DoNotOptimize(phi);
  }
}
BENCHMARK(BM_J2RoeStm);

void BM_RoeToRtnEccentric(benchmark::State& state) {
  RelativeOrbitalElements roe;
  roe << -2.62, 45.21, -34.51, 4.78, -18.72, 2.72;
  roe /= kChief.a;
  for (auto _ : state) {
    benchmark::DoNotOptimize(roe);
    RelativeRtnVector x = rtn_from_roe(kChief, roe, kGravity.mu, 100.0);
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_RoeToRtnEccentric);

void BM_RtnToRoeEccentric(benchmark::State& state) {
  RelativeRtnVector x;
  x << -34.8, 19.3, -6.9, 0.01, 0.07, -0.02;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    RelativeOrbitalElements roe = roe_from_rtn(kChief, x, kGravity.mu, 0.0);
    benchmark::DoNotOptimize(roe);
  }
}
BENCHMARK(BM_RtnToRoeEccentric);

void BM_ControlInputMatrix(benchmark::State& state) {
  KeplerianElements chief = kChief;
  for (auto _ : state) {
    benchmark::DoNotOptimize(chief);
    ControlInputMatrix g = control_input_matrix(chief, kGravity.mu);
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(BM_ControlInputMatrix);

void BM_KeplerianToCartesian(benchmark::State& state) {
  KeplerianElements el = kChief;
  for (auto _ : state) {
    benchmark::DoNotOptimize(el);
    visors::core::StateVector x = cartesian_from_keplerian(el, kGravity.mu);
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_KeplerianToCartesian);

void BM_CartesianToKeplerian(benchmark::State& state) {
  const visors::core::StateVector x = cartesian_from_keplerian(kChief, kGravity.mu);
  Eigen::Vector3d r = x.r;
  Eigen::Vector3d v = x.v;
  for (auto _ : state) {
    benchmark::DoNotOptimize(r);
    benchmark::DoNotOptimize(v);
    auto el = cartesian_to_keplerian(r, v, kGravity.mu);
    benchmark::DoNotOptimize(el);
  }
}
BENCHMARK(BM_CartesianToKeplerian);

void BM_MeanToOsculating(benchmark::State& state) {
  KeplerianElements el = kChief;
  for (auto _ : state) {
    benchmark::DoNotOptimize(el);
    auto osc = osculating_from_mean(el, kGravity);
    benchmark::DoNotOptimize(osc);
  }
}
BENCHMARK(BM_MeanToOsculating);

void BM_OsculatingToMean(benchmark::State& state) {
  KeplerianElements osc = osculating_from_mean(kChief, kGravity).value();
  for (auto _ : state) {
    benchmark::DoNotOptimize(osc);
    auto mean = mean_from_osculating(osc, kGravity);
    benchmark::DoNotOptimize(mean);
  }
}
BENCHMARK(BM_OsculatingToMean);

}  // namespace
