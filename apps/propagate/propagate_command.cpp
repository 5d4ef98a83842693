#include "apps/propagate/propagate_command.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/dynamics/files/ephemeris_file.hpp"
#include "visors/dynamics/files/force_model_files.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/dynamics/orbit_propagator.hpp"
#include "apps/propagate/propagate_scenario.hpp"

namespace visors::propagate {
namespace {

constexpr int kExitBadInput = 2;

std::vector<core::GpsTime> output_times(const PropagateScenario& s) {
  std::vector<core::GpsTime> times;
  const auto n = static_cast<std::int64_t>(std::floor(s.duration / s.output_step + 1e-9));
  times.reserve(static_cast<std::size_t>(n) + 2);
  for (std::int64_t k = 0; k <= n; ++k) times.push_back(s.epoch + static_cast<double>(k) * s.output_step);
  const core::GpsTime end = s.epoch + s.duration;
  if (times.back() < end) times.push_back(end);
  return times;
}

core::GpsTime wall_clock_now() {
  const auto since_unix = std::chrono::system_clock::now().time_since_epoch();
  // Unix epoch 1970-01-01 is 315964800 s before the GPS epoch, plus the leap seconds since.
  const double unix_s = std::chrono::duration<double>(since_unix).count();
  const core::GpsTime approx = core::GpsTime::from_seconds(unix_s - 315964800.0);
  return approx + static_cast<double>(approx.gps_minus_utc());
}

nlohmann::json vector_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// The scenario found (path, VISORS_DATA_PATH or data/) and read; nothing (printed) if not.
std::optional<PropagateScenario> load_scenario(const std::string& scenario_path) {
  const auto path = core::files::find_data_file(scenario_path);
  if (!path) {
    fmt::print(stderr, "visors propagate: scenario: '{}' not found (nor in VISORS_DATA_PATH or data/)\n",
               scenario_path);
    return std::nullopt;
  }
  auto scenario = load_propagate_scenario(*path);
  if (!scenario) {
    fmt::print(stderr, "visors propagate: {}: {}\n", path->string(), scenario.error().describe());
    return std::nullopt;
  }
  return std::move(scenario).value();
}

// The ephemeris at the output times (maneuvers applied on the way), the final state and the wall
// time of the propagation.
struct Propagation {
  std::vector<dynamics::files::EphemerisRecord> records;
  core::Result<core::StateVector> final_state;
  double wall_s;
};

Propagation propagate(dynamics::OrbitPropagator& orbit, const PropagateScenario& s) {
  const std::vector<core::GpsTime> times = output_times(s);
  std::vector<dynamics::files::EphemerisRecord> records;
  records.reserve(times.size());
  const auto start = std::chrono::steady_clock::now();
  auto final_state = orbit.propagate(
      s.epoch, s.initial_gcrf, times, s.maneuvers,
      [&records](core::GpsTime t, const core::StateVector& x) { records.push_back({t, x}); });
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Propagation{std::move(records), std::move(final_state), wall_s};
}

// <name>.csv and <name>.oem; false (printed) if either cannot be written.
bool write_ephemeris_files(const std::filesystem::path& csv_path, const std::filesystem::path& oem_path,
                           const PropagateScenario& s, const Propagation& run, const std::string& out_dir) {
  std::ofstream csv(csv_path);
  dynamics::files::write_ephemeris_csv(csv, run.records);
  std::ofstream oem(oem_path);
  dynamics::files::write_oem(oem, run.records, {s.name, "UNKNOWN", "visors_gnc", wall_clock_now()});
  if (!csv || !oem) {
    fmt::print(stderr, "visors propagate: --out: cannot write to {}\n", out_dir);
    return false;
  }
  return true;
}

// The force model's warnings plus the table look-ups of this run that fell outside the tables'
// dates; the latter are printed (the former were, at set-up).
std::vector<std::string> run_warnings(const dynamics::ForceModel& model) {
  std::vector<std::string> warnings = model.warnings();
  if (model.space_weather_misses() > 0) {
    warnings.push_back(fmt::format("forces.drag.space_weather: {} UTC days outside the table's dates used the "
                                   "configured f107/f107a/ap", model.space_weather_misses()));
  }
  if (model.ap_history_misses() > 0) {
    warnings.push_back(fmt::format("forces.drag.space_weather: {} 3-hour intervals without 57 h of ap history before "
                                   "them ran NRLMSISE-00 in its daily-Ap mode", model.ap_history_misses()));
  }
  if (model.eop_misses() > 0) {
    warnings.push_back(fmt::format("forces.earth_frame.eop: {} lookups outside the table's dates kept the last values",
                                   model.eop_misses()));
  }
  for (std::size_t k = model.warnings().size(); k < warnings.size(); ++k) {
    fmt::print(stderr, "visors propagate: warning: {}\n", warnings[k]);
  }
  return warnings;
}

nlohmann::json run_summary(const PropagateScenario& s, const Propagation& run, const astro::KeplerianElements& kf,
                           const dynamics::PropagationStats& stats, const std::vector<std::string>& warnings,
                           const std::filesystem::path& csv_path, const std::filesystem::path& oem_path) {
  const core::StateVector& xf = run.final_state.value();
  return {{"records", run.records.size()},
          {"final_time_utc", (s.epoch + s.duration).format(core::TimeScale::kUtc, 6)},
          {"final_r_gcrf", vector_json(xf.r)},
          {"final_v_gcrf", vector_json(xf.v)},
          {"final_osculating", {{"a_m", kf.a}, {"e", kf.e}, {"i_deg", kf.i / core::kDegToRad},
                                {"raan_deg", kf.raan / core::kDegToRad}, {"argp_deg", kf.argp / core::kDegToRad},
                                {"M_deg", kf.M / core::kDegToRad}}},
          {"steps", stats.steps},
          {"force_evaluations", stats.evaluations},
          {"wall_time_s", run.wall_s},
          {"warnings", warnings},
          {"csv", csv_path.string()},
          {"oem", oem_path.string()}};
}

}  // namespace

int run_propagate_command(const std::string& scenario_path, const std::string& out_dir) {
  const std::optional<PropagateScenario> scenario = load_scenario(scenario_path);
  if (!scenario) return kExitBadInput;
  const PropagateScenario& s = *scenario;
  auto forces = dynamics::files::load_force_model(s.forces, s.spacecraft);
  if (!forces) {
    fmt::print(stderr, "visors propagate: forces.{}\n", forces.error().describe());
    return kExitBadInput;
  }
  dynamics::ForceModel model = std::move(forces).value();
  for (const auto& w : model.warnings()) fmt::print(stderr, "visors propagate: warning: {}\n", w);
  auto propagator = dynamics::OrbitPropagator::create(model, s.propagator);
  if (!propagator) {
    fmt::print(stderr, "visors propagate: propagation.{}\n", propagator.error().describe());
    return kExitBadInput;
  }
  dynamics::OrbitPropagator orbit = std::move(propagator).value();
  const Propagation run = propagate(orbit, s);
  if (!run.final_state) {
    fmt::print(stderr, "visors propagate: {}\n", run.final_state.error().describe());
    return kExitBadInput;
  }

  std::filesystem::create_directories(out_dir);
  const std::filesystem::path dir(out_dir);
  const auto csv_path = dir / (s.name + ".csv");
  const auto oem_path = dir / (s.name + ".oem");
  if (!write_ephemeris_files(csv_path, oem_path, s, run, out_dir)) return kExitBadInput;
  const std::vector<std::string> warnings = run_warnings(model);
  const core::StateVector& xf = run.final_state.value();
  auto elements = astro::cartesian_to_keplerian(xf.r, xf.v, model.gm());
  if (!elements) {
    fmt::print(stderr, "visors propagate: final state is not a bound orbit ({})\n", elements.error().describe());
    return kExitBadInput;
  }
  const astro::KeplerianElements& kf = elements.value();
  const auto& stats = orbit.stats();
  std::ofstream(dir / "summary.json") << run_summary(s, run, kf, stats, warnings, csv_path, oem_path).dump(2) << '\n';
  fmt::print("{}: {} records over {:.1f} s, {} steps, {} force evaluations, {:.1f} ms\n", s.name,
             run.records.size(), s.duration, stats.steps, stats.evaluations, 1e3 * run.wall_s);
  fmt::print("final osculating a {:.3f} m, e {:.6f}, i {:.4f} deg; written {} and {}\n", kf.a, kf.e,
             kf.i / core::kDegToRad, csv_path.string(), oem_path.string());
  return 0;
}

}  // namespace visors::propagate
