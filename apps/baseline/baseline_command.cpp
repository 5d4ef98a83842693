#include "apps/baseline/baseline_command.hpp"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include <fmt/core.h>

#include "apps/baseline/baseline_outputs.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/gnss/files/rinex_nav_file.hpp"
#include "visors/gnss/files/rinex_obs_file.hpp"

namespace visors::baseline_app {
namespace {

constexpr int kExitBadInput = 2;

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A path as given, else found through the data search path.
std::filesystem::path locate(const std::string& path) {
  if (std::filesystem::exists(path)) return path;
  if (auto found = core::files::find_data_file(path)) return *found;
  return path;  // the reader names it
}

baseline::BaselineSettings settings_from(const BaselineOptions& o) {
  baseline::BaselineSettings s;
  if (o.mode == "static") s.position_model = baseline::PositionModel::kStatic;
  else if (o.mode == "kinematic") s.position_model = baseline::PositionModel::kKinematic;
  else throw InputError("--mode: '" + o.mode + "' is not static or kinematic");
  if (o.freq == "L1") s.frequencies = baseline::FrequencySet::kL1;
  else if (o.freq == "L1L2") s.frequencies = baseline::FrequencySet::kL1L2;
  else throw InputError("--freq: '" + o.freq + "' is not L1 or L1L2");
  if (o.ar == "off") s.ambiguity_mode = baseline::AmbiguityMode::kOff;
  else if (o.ar == "continuous") s.ambiguity_mode = baseline::AmbiguityMode::kContinuous;
  else if (o.ar == "hold") s.ambiguity_mode = baseline::AmbiguityMode::kHold;
  else throw InputError("--ar: '" + o.ar + "' is not off, continuous or hold");
  s.elevation_mask_deg = o.elevation_mask_deg;
  if (auto v = baseline::validate(s); !v) throw InputError("--" + v.error().field + ": " + v.error().message);
  return s;
}

baseline::ReceiverObservables load_observables(const std::string& path, const std::string& role) {
  auto file = gnss::files::read_rinex_observations(locate(path));
  if (!file) throw InputError(role + " " + file.error().describe());
  auto observables = baseline::extract_observables(file.value(), role + " " + path);
  if (!observables) throw InputError(observables.error().describe());
  return std::move(observables).value();
}

void load_navigation(const std::vector<std::string>& paths, baseline::BaselineInputs& in) {
  std::vector<gnss::BroadcastEphemeris> records;
  std::vector<std::size_t> lines;
  for (const auto& path : paths) {
    auto nav = gnss::files::read_rinex_navigation(locate(path));
    if (!nav) throw InputError("--nav " + nav.error().describe());
    if (!in.ionosphere) in.ionosphere = nav.value().ionosphere;
    records.insert(records.end(), nav.value().records.begin(), nav.value().records.end());
    lines.insert(lines.end(), nav.value().record_lines.begin(), nav.value().record_lines.end());
  }
  if (records.empty()) throw InputError("--nav: the navigation files hold no GPS record");
  in.ephemerides = gnss::EphemerisSet::screen(records, lines);
}

baseline::BaselineInputs load_inputs(const BaselineOptions& o) {
  if (o.base_ecef.size() != 3) throw InputError("--base-ecef: needs 3 values X Y Z [m]");
  baseline::BaselineInputs in;
  in.base_ecef_m = {o.base_ecef[0], o.base_ecef[1], o.base_ecef[2]};
  if (!in.base_ecef_m.allFinite() || in.base_ecef_m.norm() < 6.0e6 || in.base_ecef_m.norm() > 6.5e6) {
    throw InputError("--base-ecef: not a position near the Earth's surface (|r| must be in 6,000-6,500 km)");
  }
  if (o.nav.empty()) throw InputError("--nav: at least one navigation file is required");
  in.rover = load_observables(o.rover, "rover");
  in.base = load_observables(o.base, "base");
  load_navigation(o.nav, in);
  return in;
}

}  // namespace

int run_baseline_command(const BaselineOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  baseline::BaselineInputs inputs;
  baseline::BaselineSettings settings;
  try {
    settings = settings_from(options);
    inputs = load_inputs(options);
  } catch (const InputError& e) {
    fmt::print(stderr, "visors baseline: {}\n", e.what());
    return kExitBadInput;
  }
  auto result = baseline::process_baseline(inputs, settings);
  if (!result) {
    fmt::print(stderr, "visors baseline: {}\n", result.error().describe());
    return kExitBadInput;
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const BaselineRun run{options, settings, inputs, result.value(), wall_s};
  const auto summary = baseline_summary(run);
  if (auto written = write_outputs(run, summary); !written) {
    fmt::print(stderr, "visors baseline: {}\n", written.error().describe());
    return 1;
  }
  print_overview(run, summary);
  return 0;
}

}  // namespace visors::baseline_app
