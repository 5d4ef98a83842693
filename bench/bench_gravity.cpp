// Cost of one spherical-harmonic gravity evaluation (GGM05S_d90) at degree 20 (on board), 60
// (truth) and 90, ours (normalised Cunningham V/W) against GeographicLib::SphericalHarmonic
// (Clenshaw summation, value + gradient) in the same run. Goal: ours <= 0.5x GeographicLib.
// Needs gravity/GGM05S_d90.gfc from the repository's data/ or VISORS_DATA_PATH.
#include <benchmark/benchmark.h>

#include <GeographicLib/SphericalHarmonic.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "visors/core/files/data_path.hpp"
#include "visors/dynamics/files/icgem_file.hpp"
#include "visors/dynamics/gravity_field.hpp"
#include "visors/dynamics/spherical_harmonic_gravity.hpp"

namespace {

using visors::dynamics::GravityField;
using visors::dynamics::SphericalHarmonicGravity;

const std::optional<GravityField>& ggm05s() {
  static const std::optional<GravityField> field = []() -> std::optional<GravityField> {
    const auto path = visors::core::files::find_data_file("gravity/GGM05S_d90.gfc");
    if (!path) return std::nullopt;
    auto read = visors::dynamics::files::read_icgem(*path);
    if (!read.ok()) return std::nullopt;
    return std::move(read).value();
  }();
  return field;
}

// The machine is shared: with --benchmark_repetitions=N the minimum over repetitions is the
// least disturbed estimate of the cost.
double minimum(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

constexpr const char* kMissing =
    "gravity/GGM05S_d90.gfc not found: set VISORS_DATA_PATH to the shared data folder";

// 64 positions on a 500 km, 97.4 deg orbit-like shell (varying latitude and longitude), cycled so
// that no call sees the same input twice in a row.
std::vector<Eigen::Vector3d> leo_positions() {
  std::vector<Eigen::Vector3d> points;
  const double r = 6378136.3 + 500e3;
  for (int i = 0; i < 64; ++i) {
    const double u = 2.0 * std::numbers::pi * i / 64.0;
    const double lon = 0.37 * i;
    const double sin_lat = std::sin(u) * std::sin(97.4 * std::numbers::pi / 180.0);
    const double cos_lat = std::sqrt(1.0 - sin_lat * sin_lat);
    points.emplace_back(r * cos_lat * std::cos(lon), r * cos_lat * std::sin(lon), r * sin_lat);
  }
  return points;
}

// Our evaluation `call(gravity, r)` at degree = order = the benchmark argument.
template <typename Call>
void bench_ours(benchmark::State& state, Call call) {
  if (!ggm05s()) {
    state.SkipWithError(kMissing);
    return;
  }
  const int n = static_cast<int>(state.range(0));
  SphericalHarmonicGravity g = SphericalHarmonicGravity::create(*ggm05s(), n, n).value();
  const std::vector<Eigen::Vector3d> points = leo_positions();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(call(g, points[i++ & 63]));
  }
}

void BM_OursAcceleration(benchmark::State& state) {
  bench_ours(state, [](SphericalHarmonicGravity& g, const Eigen::Vector3d& r) { return g.acceleration(r); });
}
BENCHMARK(BM_OursAcceleration)->Arg(20)->Arg(60)->Arg(90)->ComputeStatistics("min", minimum);

void BM_OursAccelerationAndPotential(benchmark::State& state) {
  bench_ours(state, [](SphericalHarmonicGravity& g, const Eigen::Vector3d& r) {
    return g.acceleration_and_potential(r);
  });
}
BENCHMARK(BM_OursAccelerationAndPotential)->Arg(20)->Arg(60)->Arg(90)->ComputeStatistics("min", minimum);

void BM_OursGradient(benchmark::State& state) {
  bench_ours(state, [](SphericalHarmonicGravity& g, const Eigen::Vector3d& r) { return g.gradient(r); });
}
BENCHMARK(BM_OursGradient)->Arg(20)->Arg(60)->Arg(90)->ComputeStatistics("min", minimum);

// GeographicLib with the same coefficients (FULL normalisation, column-major by order; see the
// oracle in tests/dynamics/test_spherical_harmonic_gravity.cpp): value and gradient per call.
void BM_GeographicLibValueAndGradient(benchmark::State& state) {
  if (!ggm05s()) {
    state.SkipWithError(kMissing);
    return;
  }
  const GravityField& field = *ggm05s();
  const int n = static_cast<int>(state.range(0));
  std::vector<double> c(static_cast<std::size_t>((n + 1) * (n + 2) / 2), 0.0);
  std::vector<double> s(static_cast<std::size_t>(n * (n + 1) / 2), 0.0);
  for (int m = 0; m <= n; ++m) {
    for (int k = m; k <= n; ++k) {
      const int idx = m * n - m * (m - 1) / 2 + k;
      c[static_cast<std::size_t>(idx)] = field.c(k, m);
      if (m > 0) s[static_cast<std::size_t>(idx - (n + 1))] = field.s(k, m);
    }
  }
  const GeographicLib::SphericalHarmonic harmonic(c, s, n, field.radius, GeographicLib::SphericalHarmonic::FULL);
  const std::vector<Eigen::Vector3d> points = leo_positions();
  std::size_t i = 0;
  for (auto _ : state) {
    const Eigen::Vector3d& r = points[i++ & 63];
    double gx = 0.0, gy = 0.0, gz = 0.0;
    benchmark::DoNotOptimize(harmonic(r.x(), r.y(), r.z(), gx, gy, gz));
    benchmark::DoNotOptimize(gx);
    benchmark::DoNotOptimize(gy);
    benchmark::DoNotOptimize(gz);
  }
}
BENCHMARK(BM_GeographicLibValueAndGradient)->Arg(20)->Arg(60)->Arg(90)->ComputeStatistics("min", minimum);

}  // namespace
