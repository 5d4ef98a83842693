#pragma once
// What one run of a Monte Carlo campaign produced: its status, wall time, the error when it
// failed, and the run's summary (sim::CampaignSimulation::summary, docs/run-directory.md) when it
// finished. Sent from the process or rank that ran it to the one that stores it as JSON text.

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "visors/core/result.hpp"
#include "visors/mc/run_plan.hpp"

namespace visors::mc {

struct RunRecord {
  std::int64_t run = 0;
  bool ok = false;
  double wall_s = 0.0;
  std::string error;        // why it failed (empty when ok)
  nlohmann::json summary;   // the run's summary.json (null when failed)
};

std::string to_json_text(const RunRecord& record);
core::Result<RunRecord> run_record_from_json_text(const std::string& text);

/// Runs `run` of `campaign` in this process, its run directory under `scratch` (removed after,
/// unless keep); never throws: an exception or an error of the simulation is a failed record.
/// Test hook: the environment variable VISORS_MC_INJECT = "throw@N", "crash@N" or "hang@N" makes
/// run N throw, abort, or sleep past any time limit (the pool's failure paths are tested with it).
RunRecord execute_run(const Campaign& campaign, const RunSpec& run, const std::filesystem::path& scratch, bool keep);

}  // namespace visors::mc
