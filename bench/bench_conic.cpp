// Solve time of the embedded conic solver on the minimum-fuel planner shape, and CVXOPT on the
// same instances for the ratio (the solver's performance goal: median below 100 us for 30
// impulses).
//   min sum_k t_k  s.t.  sum_k B_k dv_k = target (6 rows),  ||dv_k|| <= t_k,  k = 1..N
// with B random normal (an STM-like 6 x 3N map) and a random target, N = 10, 30, 60, 40 seeded
// instances each. BM_ConicSolve/N reports per-instance median and worst (counters median_us,
// worst_us); BM_CvxoptReference/N writes the same instances to a temporary JSON file and runs
//   /usr/bin/python3 tests/optim/cvxopt_oracle.py --bench FILE
// (best of 3 per instance, conelp at tolerances 1e-8), reporting cvxopt_median_us,
// cvxopt_worst_us and ratio = CVXOPT median / our median. Run:
//   ninja -C build visors_bench_conic && build/bench/visors_bench_conic

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#include "visors/optim/conic_solver.hpp"
#include "optim/minimum_fuel_problem.hpp"

namespace {

using visors::optim::ConicDimensions;
using visors::optim::ConicProblem;
using visors::optim::ConicSolver;

constexpr int kInstances = 40;

std::vector<ConicProblem> fuel_instances(int impulses) {
  std::mt19937 rng(static_cast<unsigned>(1000 + impulses));
  std::vector<ConicProblem> out;
  for (int k = 0; k < kInstances; ++k) {
    out.push_back(visors::optim::test::minimum_fuel_problem(impulses, rng));
  }
  return out;
}

std::map<int, double>& our_median() {
  static std::map<int, double> medians;
  return medians;
}

void BM_ConicSolve(benchmark::State& state) {
  const int impulses = static_cast<int>(state.range(0));
  const auto instances = fuel_instances(impulses);
  auto created = ConicSolver::create(visors::optim::test::minimum_fuel_dimensions(impulses));
  if (!created.ok()) {
    state.SkipWithError(created.error().describe().c_str());
    return;
  }
  ConicSolver solver = std::move(created).value();
  std::vector<double> times;
  std::vector<int> iterations;
  int failures = 0;
  int fallbacks = 0;
  std::size_t next = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto info = solver.solve(instances[next]);
    const auto t1 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(info);
    times.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    iterations.push_back(info.ok() ? info->iterations : -1);
    if (!info.ok() || info->status != visors::optim::ConicStatus::kOptimal) ++failures;
    if (info.ok()) fallbacks += info->dense_fallbacks;
    next = (next + 1) % instances.size();
  }
  std::sort(times.begin(), times.end());
  std::sort(iterations.begin(), iterations.end());
  const double median = times[times.size() / 2];
  our_median()[impulses] = median;
  state.counters["median_us"] = median;
  state.counters["worst_us"] = times.back();
  state.counters["median_iterations"] = iterations[iterations.size() / 2];
  state.counters["not_optimal"] = failures;
  state.counters["dense_fallbacks_per_solve"] = static_cast<double>(fallbacks) / static_cast<double>(times.size());
}
BENCHMARK(BM_ConicSolve)->Arg(10)->Arg(30)->Arg(60)->Iterations(4 * kInstances)->Unit(benchmark::kMicrosecond);

std::filesystem::path source_dir() {
  if (const char* env = std::getenv("VISORS_SOURCE_DIR")) return env;
  return std::filesystem::path(__FILE__).parent_path().parent_path();
}

void write_instances(const std::filesystem::path& path, const std::vector<ConicProblem>& instances,
                     const ConicDimensions& dims) {
  std::ofstream out(path);
  out.precision(17);
  const auto vec = [&](const Eigen::VectorXd& v) {
    out << '[';
    for (Eigen::Index i = 0; i < v.size(); ++i) out << (i ? "," : "") << v(i);
    out << ']';
  };
  const auto mat = [&](const Eigen::MatrixXd& m) {
    out << '[';
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
      out << (r ? "," : "");
      vec(m.row(r).transpose());
    }
    out << ']';
  };
  out << "{\"instances\":[";
  for (std::size_t k = 0; k < instances.size(); ++k) {
    const auto& pr = instances[k];
    out << (k ? "," : "") << "{\"n\":" << dims.n << ",\"l\":0,\"p\":6,\"q\":[";
    for (std::size_t j = 0; j < dims.q.size(); ++j) out << (j ? "," : "") << dims.q[j];
    out << "],\"c\":";
    vec(pr.c);
    out << ",\"G\":";
    mat(pr.G);
    out << ",\"h\":";
    vec(pr.h);
    out << ",\"A\":";
    mat(pr.A);
    out << ",\"b\":";
    vec(pr.b);
    out << '}';
  }
  out << "]}";
}

void BM_CvxoptReference(benchmark::State& state) {
  const int impulses = static_cast<int>(state.range(0));
  const auto path = std::filesystem::temp_directory_path() /
                    ("visors_bench_conic_" + std::to_string(::getpid()) + "_" + std::to_string(impulses) + ".json");
  write_instances(path, fuel_instances(impulses), visors::optim::test::minimum_fuel_dimensions(impulses));
  const std::string command =
      "/usr/bin/python3 '" + (source_dir() / "tests/optim/cvxopt_oracle.py").string() + "' --bench '" + path.string() + "'";
  double median = 0.0, worst = 0.0;
  for (auto _ : state) {
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr || std::fscanf(pipe, "%lf %lf", &median, &worst) != 2) {
      if (pipe != nullptr) ::pclose(pipe);
      state.SkipWithError("CVXOPT reference run failed (needs /usr/bin/python3 with python3-cvxopt)");
      break;
    }
    ::pclose(pipe);
  }
  std::filesystem::remove(path);
  state.counters["cvxopt_median_us"] = median;
  state.counters["cvxopt_worst_us"] = worst;
  if (our_median().count(impulses) != 0 && our_median()[impulses] > 0.0) {
    state.counters["ratio_cvxopt_over_ours"] = median / our_median()[impulses];
  }
}
BENCHMARK(BM_CvxoptReference)->Arg(10)->Arg(30)->Arg(60)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
