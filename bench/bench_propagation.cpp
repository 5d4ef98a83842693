// Orbit propagation cost (the propagator's cost goal,
// docs/algorithms/dynamics.md#propagator-acceptance): one orbit of
// RK4 at 30 s with 80x80 gravity, Sun, Moon, drag and SRP (goal < 15 ms); one day of the truth
// model at its step; the force model per evaluation for the on-board and truth presets. The
// gravity files are found in the repository's data/ or VISORS_DATA_PATH (without them the
// embedded degree-8 field is used and the result says so).

#include <benchmark/benchmark.h>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/dynamics/files/force_model_files.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/dynamics/orbit_propagator.hpp"

namespace {
using namespace visors;
using namespace visors::dynamics;

const core::GpsTime kEpoch = core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kUtc).value();

core::StateVector mission_chief() {
  return astro::cartesian_from_keplerian(
      {6878136.3, 0.004, 97.8 * core::kDegToRad, 157.5 * core::kDegToRad, 90.0 * core::kDegToRad, 0.0},
      3.986004415e14);
}

// The published comparison task: 80x80 gravity, Sun, Moon, drag, SRP (no EOP file).
ForceModelConfig full_80x80() {
  ForceModelConfig c = ForceModelConfig::truth();
  c.gravity = {"gravity/GGM05S_d90.gfc", 80, 80, true};
  c.earth_frame.eop.clear();
  return c;
}

bool make(benchmark::State& state, const ForceModelConfig& config, std::optional<ForceModel>& forces) {
  auto created = dynamics::files::load_force_model(config, SpacecraftProperties{});
  if (!created) {
    state.SkipWithError(created.error().describe().c_str());
    return false;
  }
  forces.emplace(std::move(created).value());
  if (!forces->warnings().empty()) state.SetLabel(forces->warnings().front());
  return true;
}

void propagate(benchmark::State& state, const ForceModelConfig& config, double step, double duration) {
  std::optional<ForceModel> forces;
  if (!make(state, config, forces)) return;
  PropagatorSettings settings;
  settings.integrator = IntegratorKind::kRk4Fixed;
  settings.step_s = step;
  settings.min_step_s = step;
  OrbitPropagator propagator = OrbitPropagator::create(*forces, settings).value();
  const core::StateVector x0 = mission_chief();
  for (auto _ : state) {
    auto x1 = propagator.propagate_to(kEpoch, x0, kEpoch + duration);
    benchmark::DoNotOptimize(x1);
  }
  state.counters["evaluations"] =
      static_cast<double>(propagator.stats().evaluations) / static_cast<double>(state.iterations());
}

void BM_OneOrbitRk4_30s_80x80_AllForces(benchmark::State& state) { propagate(state, full_80x80(), 30.0, 5700.0); }
BENCHMARK(BM_OneOrbitRk4_30s_80x80_AllForces)->Unit(benchmark::kMillisecond);

void BM_OneDayTruthRk4_2s(benchmark::State& state) {
  propagate(state, ForceModelConfig::truth(), 2.0, 86400.0);
}
BENCHMARK(BM_OneDayTruthRk4_2s)->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_OneOrbitOnboardRk4_10s(benchmark::State& state) {
  propagate(state, ForceModelConfig::onboard(), 10.0, 5700.0);
}
BENCHMARK(BM_OneOrbitOnboardRk4_10s)->Unit(benchmark::kMillisecond);

void evaluate(benchmark::State& state, const ForceModelConfig& config) {
  std::optional<ForceModel> forces;
  if (!make(state, config, forces)) return;
  const core::StateVector x = mission_chief();
  core::GpsTime t = kEpoch;
  for (auto _ : state) {
    t += std::chrono::nanoseconds(1'000'000);  // 1 ms: the frame cache behaves as in a propagation
    benchmark::DoNotOptimize(forces->acceleration(t, x));
  }
}

void BM_ForceModelOnboard(benchmark::State& state) { evaluate(state, ForceModelConfig::onboard()); }
BENCHMARK(BM_ForceModelOnboard);
void BM_ForceModelTruth(benchmark::State& state) { evaluate(state, ForceModelConfig::truth()); }
BENCHMARK(BM_ForceModelTruth);
void BM_ForceModel80x80AllForces(benchmark::State& state) { evaluate(state, full_80x80()); }
BENCHMARK(BM_ForceModel80x80AllForces);

}  // namespace
