#include "apps/run/run_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

#include <fmt/core.h>

#include "visors/core/files/data_path.hpp"
#include "visors/core/files/text_file.hpp"
#include "visors/report/report.hpp"
#include "visors/sim/campaign_simulation.hpp"
#include "visors/sim/gnss_simulation.hpp"

namespace visors::run {
namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitFailed = 1;

// Simulated time, speed-up and ETA on one refreshed terminal line (only when stderr is a
// terminal, so logs and CI output stay clean).
void show_progress(const sim::RunProgress& p) {
  static double last_wall = -1.0;
  if (p.wall_s - last_wall < 0.5) return;
  last_wall = p.wall_s;
  const double speed = p.wall_s > 0.0 ? p.simulated_s / p.wall_s : 0.0;
  const double eta = speed > 0.0 ? (p.total_s - p.simulated_s) / speed : 0.0;
  fmt::print(stderr, "\r  simulated {:8.0f} s ({:5.1f} h)   {:7.0f}x real time   ETA {:5.0f} s   ", p.simulated_s,
             p.simulated_s / 3600.0, speed, eta);
}

// The command that starts a flight software process: `command` split at spaces, or the
// visors-fsw beside this program.
std::vector<std::string> fsw_process_command(const FswOptions& fsw) {
  if (fsw.mode != "process") return {};
  std::vector<std::string> words;
  std::istringstream in(fsw.command);
  for (std::string word; in >> word;) words.push_back(word);
  if (words.empty()) {
    std::error_code error;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
    words.push_back(error ? std::string("visors-fsw") : (self.parent_path() / "visors-fsw").string());
  }
  return words;
}

}  // namespace

std::optional<sim::CampaignScenario> load_scenario(const std::string& scenario_path, const char* command) {
  const auto path = core::files::find_data_file(scenario_path);
  if (!path) {
    fmt::print(stderr, "{}: scenario: '{}' not found (nor in VISORS_DATA_PATH or data/)\n", command, scenario_path);
    return std::nullopt;
  }
  const auto text = core::files::read_text_file(*path);
  if (!text) {
    fmt::print(stderr, "{}: {}: cannot be read\n", command, path->string());
    return std::nullopt;
  }
  auto scenario = sim::campaign_from_toml(*text);
  if (!scenario.ok()) {
    fmt::print(stderr, "{}: {}: {}\n", command, path->string(), scenario.error().describe());
    return std::nullopt;
  }
  fmt::print("{}: {} ({}), seed {}\n", command, scenario->name, path->string(), scenario->seed);
  return std::move(scenario).value();
}

// The run's "warning" events (data files not found and the embedded defaults used instead), each
// message once, on stderr: a fallback must not be visible only in the event log.
void print_warnings(const std::filesystem::path& dir) {
  std::ifstream events(dir / "events.csv");
  std::vector<std::string> seen;
  for (std::string line; std::getline(events, line);) {
    const std::size_t kind = line.find(",warning,");
    if (kind == std::string::npos) continue;
    std::string message = line.substr(kind + 9);
    if (message.size() >= 2 && message.front() == '"' && message.back() == '"') message = message.substr(1, message.size() - 2);
    if (std::find(seen.begin(), seen.end(), message) != seen.end()) continue;
    seen.push_back(message);
    fmt::print(stderr, "  warning: {}\n", message);
  }
}

int run_campaign_command(const std::string& scenario_path, const std::string& out_dir, int threads, const FswOptions& fsw) {
  const auto scenario = load_scenario(scenario_path, "visors run");
  if (!scenario) return kExitBadInput;
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  auto result = sim::run_campaign(*scenario, out_dir, terminal ? std::function<void(const sim::RunProgress&)>(show_progress)
                                                               : std::function<void(const sim::RunProgress&)>(),
                                 sim::RunOptions{.parallel_components = threads >= 2, .fsw_command = fsw_process_command(fsw)});
  if (terminal) fmt::print(stderr, "\n");
  if (!result.ok()) {
    fmt::print(stderr, "visors run: {}\n", result.error().describe());
    return kExitFailed;
  }
  print_warnings(result->dir);
  const auto& s = result->summary;
  fmt::print("  simulated {:.0f} s in {:.1f} s ({:.0f}x real time)\n", s["simulated_s"].get<double>(), s["wall_s"].get<double>(),
             s["simulated_s"].get<double>() / std::max(1e-9, s["wall_s"].get<double>()));
  fmt::print("  observations: {} attempted, success rate {:.0f} % (requirement >= 20 %)\n", s["observations"].size(),
             100.0 * s["success_rate"].get<double>());
  fmt::print("  delta-v (L1, thrusters' frame): DSC {:.4f} m/s, OSC {:.4f} m/s\n", s["delta_v_mps"]["dsc"]["total"].get<double>(),
             s["delta_v_mps"]["osc"]["total"].get<double>());
  fmt::print("  min separation: RN {:.2f} m, 3D {:.2f} m; passive-safety violations: {}; final mode: {}\n",
             s["min_separation_rn_m"].get<double>(), s["min_separation_3d_m"].get<double>(), s["safety_violations"].get<int>(),
             s["final_mode"].get<std::string>());
  auto report = report::write_report(result->dir);
  if (!report.ok()) {
    fmt::print(stderr, "visors run: report: {}\n", report.error().describe());
    return kExitFailed;
  }
  fmt::print("  run directory {}\n  report {}\n", result->dir.string(), report->string());
  return 0;
}

int run_gnss_sim_command(const std::string& scenario_path, const std::string& out_dir) {
  const auto scenario = load_scenario(scenario_path, "visors gnss-sim");
  if (!scenario) return kExitBadInput;
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  auto result = sim::run_gnss_simulation(*scenario, out_dir,
                                         terminal ? std::function<void(const sim::RunProgress&)>(show_progress)
                                                  : std::function<void(const sim::RunProgress&)>());
  if (terminal) fmt::print(stderr, "\n");
  if (!result.ok()) {
    fmt::print(stderr, "visors gnss-sim: {}\n", result.error().describe());
    return result.error().field.rfind("gnss", 0) == 0 ? kExitBadInput : kExitFailed;
  }
  const auto& s = result->summary;
  fmt::print("  {} epochs ({:.0f} s) in {:.1f} s; receivers {:.1f} us per epoch for both spacecraft\n",
             s["epochs"].get<long>(), s["duration_s"].get<double>(), s["wall_s"].get<double>(),
             s["receiver_us_per_epoch_two_spacecraft"].get<double>());
  for (const char* name : {"dsc", "osc"}) {
    const auto& r = s["receivers"][name];
    fmt::print("  {}: {:.2f} satellites visible, {:.2f} tracked on average, {} acquisitions and slips\n", name,
               r["mean_visible"].get<double>(), r["mean_tracked"].get<double>(), r["acquisitions_and_slips"].get<long>());
  }
  fmt::print("  output {}\n", result->dir.string());
  return 0;
}

}  // namespace visors::run
