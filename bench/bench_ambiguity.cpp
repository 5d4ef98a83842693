// Integer ambiguity resolution (benchmarks of the flight step): decorrelation + MLAMBDA search of
// the m = 2 best candidates, IntegerLeastSquares::resolve, on the two families of
// ambiguity_instances.hpp (single-epoch L1/L2 DD geometry; random SPD of condition 1e6), 50 seeded
// instances each for n = 8, 16, 24, timed as a sweep over the 50 (one iteration = 50 calls).
// Counters: median_us and worst_us per call, failures (search limit or any non-ok status),
// mean_steps (search steps per call) and mean_permutations (reduction).
// Peer on the same instances: scripts/bench_rtklib_lambda.sh (RTKLIB lambda(), same machine).
// Run: ninja -C build visors_bench_ambiguity && build/bench/visors_bench_ambiguity

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "ambiguity_instances.hpp"
#include "visors/nav/integer_least_squares.hpp"

namespace {

using visors::nav::IlsStatus;
using visors::nav::IntegerLeastSquares;

void sweep(benchmark::State& state, const std::vector<visors::bench::IlsInstance>& instances) {
  auto ils = IntegerLeastSquares::create().value();
  std::vector<double> per_call_us;
  long failures = 0, steps = 0, permutations = 0, calls = 0;
  for (auto _ : state) {
    for (const visors::bench::IlsInstance& inst : instances) {
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

void BM_IlsDualFrequencyDd(benchmark::State& state) { sweep(state, visors::bench::dd_family(static_cast<int>(state.range(0)))); }
void BM_IlsRandomSpd(benchmark::State& state) { sweep(state, visors::bench::random_spd_family(static_cast<int>(state.range(0)))); }

BENCHMARK(BM_IlsDualFrequencyDd)->Arg(8)->Arg(16)->Arg(24)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_IlsRandomSpd)->Arg(8)->Arg(16)->Arg(24)->Unit(benchmark::kMicrosecond);

}  // namespace
