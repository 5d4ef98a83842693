#pragma once
// The closed-loop mission simulation of `visors run`: the truth world (both spacecraft under the
// truth force model, attitude profile and attitude-dependent drag area, propulsion with its
// errors, payload geometry with its errors), ideal navigation, a delayed crosslink, the host
// application emulator (channel routing, the ground timeline, FDIR responses) and one GNC
// flight component per spacecraft, stepped together at the 1 Hz channel rate.
//
// Host application (mission paper, FDIR): ground commands follow the scenario timeline
// (to_standby at t0, start_science after standby_s); when the active spacecraft reports a
// passive-safety violation the host commands it to escape; when the active spacecraft reports
// GNC incapable for a minute, the host switches roles (the other spacecraft becomes active).

#include <filesystem>
#include <functional>

#include <nlohmann/json.hpp>

#include "core/status.hpp"
#include "sim/campaign_scenario.hpp"

namespace visors::sim {

struct RunProgress {
  double simulated_s = 0.0;
  double total_s = 0.0;  // the scenario's upper bound (max_duration_s)
  double wall_s = 0.0;
};

struct RunResult {
  nlohmann::json summary;
  std::filesystem::path dir;
};

/// Runs `scenario`, writing the run directory `out_dir`. `progress` (optional) is called about
/// every simulated minute. Errors: model set-up (named field), output files, a truth state
/// that fails (re-entry).
core::Result<RunResult> run_campaign(const CampaignScenario& scenario, const std::filesystem::path& out_dir,
                                     const std::function<void(const RunProgress&)>& progress = {});

}  // namespace visors::sim
