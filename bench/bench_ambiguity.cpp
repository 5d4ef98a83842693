// Integer ambiguity resolution (issue 14 benchmarks): decorrelation + MLAMBDA search of the m = 2
// best candidates, IntegerLeastSquares::resolve, on two families of 50 seeded instances each for
// n = 8, 16, 24, timed as a sweep over the 50 (one iteration = 50 calls):
// (1) single-epoch dual-frequency short-baseline DD geometry (tests/support/dd_geometry.hpp):
//     n/2 + 1 satellites, azimuth uniform, sin(elevation) uniform in [sin 10 deg, 1], highest as
//     reference, baseline + n ambiguities (L1, L2), 3 mm phase and 0.3 m code undifferenced, DD
//     cofactor 2(I + 11'); integers uniform in +-1e6 plus noise from Q;
// (2) random SPD Q = U diag(ev) U', U Haar orthogonal, ev log-spaced in [1e-6, 1] cycles^2
//     (condition 1e6), float ambiguities uniform in +-1e6.
// Counters: median_us and worst_us per call, failures (search limit or any non-ok status),
// mean_steps (search steps per call) and mean_permutations (reduction).
// Reference (issue 14): RTKLIB lambda() takes 100-104 us per call on family (1) at n = 24 on this
// machine type and fails its 10,000-step cap on 6 of 50 family-(2) problems at n = 24.
// Run: ninja -C build visors_bench_ambiguity && build/bench/visors_bench_ambiguity

#include <benchmark/benchmark.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <chrono>
#include <random>
#include <vector>

#include "nav/integer_least_squares.hpp"
#include "support/dd_geometry.hpp"
#include "support/random_orthogonal.hpp"

namespace {

using visors::nav::IlsStatus;
using visors::nav::IntegerLeastSquares;

struct Instance {
  Eigen::VectorXd a;
  Eigen::MatrixXd Q;
};

std::vector<Instance> dd_family(int n) {
  std::vector<Instance> out;
  std::mt19937_64 rng(1400 + n);
  visors::test::DdGeometryOptions o;
  o.satellites = n / 2 + 1;
  o.frequencies = 2;
  for (int k = 0; k < 50; ++k) {
    Instance inst;
    inst.Q = visors::test::dd_ambiguity_covariance(o, rng);
    const Eigen::MatrixXd chol = inst.Q.llt().matrixL();
    inst.a = visors::test::float_ambiguities(visors::test::random_integers(n, 1e6, rng), chol, rng);
    out.push_back(inst);
  }
  return out;
}

std::vector<Instance> random_spd_family(int n) {
  std::vector<Instance> out;
  std::mt19937_64 rng(2400 + n);
  std::uniform_real_distribution<double> offset(-1e6, 1e6);
  Eigen::VectorXd ev(n);
  for (int i = 0; i < n; ++i) ev(i) = std::pow(10.0, -6.0 + 6.0 * i / (n - 1));  // log-spaced [1e-6, 1]
  for (int k = 0; k < 50; ++k) {
    Instance inst;
    inst.Q = visors::test::spd_with_eigenvalues(visors::test::haar_orthogonal(n, rng), ev);
    inst.a.resize(n);
    for (int i = 0; i < n; ++i) inst.a(i) = offset(rng);
    out.push_back(inst);
  }
  return out;
}

void sweep(benchmark::State& state, const std::vector<Instance>& instances) {
  auto ils = IntegerLeastSquares::create().value();
  std::vector<double> per_call_us;
  long failures = 0, steps = 0, permutations = 0, calls = 0;
  for (auto _ : state) {
    for (const Instance& inst : instances) {
      const auto t0 = std::chrono::steady_clock::now();
      const IlsStatus status = ils.resolve(inst.a, inst.Q);
      const auto t1 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(ils.solution().sqnorm.data());
      per_call_us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
      if (status != IlsStatus::kOk) ++failures;
      steps += ils.solution().search_steps;
      permutations += ils.decorrelated().decorrelation.permutations;
      ++calls;
    }
  }
  std::sort(per_call_us.begin(), per_call_us.end());
  state.counters["median_us"] = per_call_us[per_call_us.size() / 2];
  state.counters["worst_us"] = per_call_us.back();
  state.counters["failures"] = static_cast<double>(failures) / static_cast<double>(state.iterations());
  state.counters["mean_steps"] = static_cast<double>(steps) / static_cast<double>(calls);
  state.counters["mean_permutations"] = static_cast<double>(permutations) / static_cast<double>(calls);
}

void BM_IlsDualFrequencyDd(benchmark::State& state) { sweep(state, dd_family(static_cast<int>(state.range(0)))); }
void BM_IlsRandomSpd(benchmark::State& state) { sweep(state, random_spd_family(static_cast<int>(state.range(0)))); }

BENCHMARK(BM_IlsDualFrequencyDd)->Arg(8)->Arg(16)->Arg(24)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IlsRandomSpd)->Arg(8)->Arg(16)->Arg(24)->Unit(benchmark::kMicrosecond);

}  // namespace
