#pragma once
// `visors run [SCENARIO.toml] [--out DIR]`: the mission campaign in closed loop (two flight
// components, truth world, ideal navigation), its run directory and HTML report.

#include <optional>
#include <string>

#include "visors/sim/campaign_scenario.hpp"

namespace visors::run {

/// The scenario at `scenario_path` (a path, or relative to the data search path), or nullopt
/// after printing "<command>: <file>: <field>: <problem>" to stderr.
std::optional<sim::CampaignScenario> load_scenario(const std::string& scenario_path, const char* command);

/// `visors gnss-sim [SCENARIO.toml] [--out DIR]`: sim/gnss_simulation.hpp. Exit codes as below.
int run_gnss_sim_command(const std::string& scenario_path, const std::string& out_dir);

/// Where the flight software runs (`--fsw`, `--fsw-command`; docs/flight-software-process.md).
struct FswOptions {
  std::string mode = "in-process";  // or "process"
  std::string command;  // split at spaces; empty: the visors-fsw beside this program
};

/// Returns the process exit code: 0 on success, 2 on bad input, 1 when the simulation fails.
/// threads: 2 steps the two flight components side by side (sim::RunOptions), 1 in turn.
int run_campaign_command(const std::string& scenario_path, const std::string& out_dir, int threads = 2,
                         const FswOptions& fsw = {});

}  // namespace visors::run
