#pragma once
// `visors run [SCENARIO.toml] [--out DIR]`: the mission campaign in closed loop (two flight
// components, truth world, ideal navigation), its run directory and HTML report.

#include <string>

namespace visors::run {

/// Returns the process exit code: 0 on success, 2 on bad input, 1 when the simulation fails.
int run_campaign_command(const std::string& scenario_path, const std::string& out_dir);

}  // namespace visors::run
