#pragma once
// The Monte Carlo campaign file of `visors mc` (TOML; data/campaigns/*.toml, docs/monte-carlo.md):
// a base scenario of `visors run`, fixed changes to it, dispersions of any scenario key drawn per
// run, and sweeps (a key and its values, `runs_per_value` runs each).
//
//   name = "paper_sensitivity"
//   scenario = "scenarios/campaign.toml"  # relative to this file, or on the data search path
//   seed = 1                              # base seed: every run's seed derives from it
//   runs = 20                             # without sweeps: the number of runs
//   runs_per_value = 10                   # with sweeps: runs per swept value
//   time_limit_s = 900.0                  # wall time a run may take before it is stopped
//   paired = true                         # common random numbers across a sweep's values
//   [set]                                 # fixed changes: "section.key" = value
//   "navigation.mode" = "ideal"
//   [dispersions]                         # drawn per run
//   "propulsion.isp_s" = { normal = { mean = 44.0, sigma = 2.0 } }
//   "crosslink.delay_s" = { uniform = { min = 0.2, max = 1.0 } }
//   "navigation.mode" = { choice = ["ideal", "cdgps"] }
//   [[sweep]]
//   key = "geometry.com_knowledge_error_m"
//   values = [0.0, 0.005, 0.01]
//
// Keys are the scenario's own ("section.key", docs/scenario.md gives each one's unit); a value's
// type and range are checked by the scenario's reader when the campaign is read (every set value,
// every swept value, each dispersion's extremes), so a bad key fails before any run starts, with
// an error naming where it was written ("sweep[2].values", "dispersions.\"propulsion.isp_s\"").

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "visors/core/result.hpp"
#include "visors/mc/scenario_value.hpp"

namespace visors::mc {

struct Dispersion {
  enum class Kind { kNormal, kUniform, kChoice };
  std::string key;
  Kind kind = Kind::kNormal;
  double a = 0.0;  // normal: mean; uniform: min
  double b = 0.0;  // normal: sigma (>= 0); uniform: max (>= min)
  std::vector<ScenarioValue> choices;
};

struct Sweep {
  std::string key;
  std::vector<ScenarioValue> values;
};

struct Campaign {
  std::string name;
  std::string text;                    // the campaign file as read
  std::filesystem::path scenario_path; // the base scenario found
  std::string scenario_text;           // and its text
  std::uint64_t seed = 1;
  std::int64_t runs = 1;               // without sweeps
  std::int64_t runs_per_value = 1;     // with sweeps
  double time_limit_s = 3600.0;
  bool paired = true;
  std::vector<std::pair<std::string, ScenarioValue>> set;
  std::vector<Dispersion> dispersions;
  std::vector<Sweep> sweeps;

  /// Total number of runs: `runs` without sweeps, else runs_per_value x all swept values.
  [[nodiscard]] std::int64_t total_runs() const;
};

/// Parses a campaign file's text; `directory` is where it lies (for a relative base scenario),
/// or `scenario_text` the base scenario's text (as a results store recorded it: not looked up).
/// Checks every key against the base scenario (file comment). Errors name the field.
core::Result<Campaign> campaign_from_toml(const std::string& text, const std::filesystem::path& directory,
                                          const std::optional<std::string>& scenario_text = std::nullopt);

/// Reads and parses the campaign file at `path` (a path, or relative to the data search path).
core::Result<Campaign> load_campaign(const std::string& path);

}  // namespace visors::mc
