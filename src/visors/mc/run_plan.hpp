#pragma once
// The runs of a Monte Carlo campaign: run i's sweep value, replicate, seed and drawn dispersion
// values, and its scenario. Everything derives from the campaign and i alone, so any run can be
// re-run by itself (`visors mc rerun`) and the results do not depend on how runs are distributed
// over threads, processes or MPI ranks.
//
// Order: sweep by sweep in the file's order, value by value, runs_per_value replicates each
// (index = first run of the sweep + value x runs_per_value + replicate); without sweeps, runs
// 0..runs-1 are replicates of the base.
//
// Seeds: run_seed = splitmix64(seed ^ splitmix64(stream)) masked to 63 bits (the scenario's seed is
// a TOML integer >= 0), with stream = the replicate when `paired` (common random numbers: the r-th
// run of every swept value sees the same noise, so the sweep's differences are the parameter's),
// else the run index. splitmix64: Steele, Lea & Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014.
//
// Dispersions: each key drawn from its own stream RandomStream(run_seed, "mc." + key), one draw,
// so adding a dispersion never shifts another's value.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "visors/core/result.hpp"
#include "visors/mc/campaign_file.hpp"
#include "visors/sim/campaign_scenario.hpp"

namespace visors::mc {

struct RunSpec {
  std::int64_t index = 0;
  int sweep = -1;            // index into Campaign::sweeps, -1 without sweeps
  int value = -1;            // index into that sweep's values
  std::int64_t replicate = 0;
  std::uint64_t seed = 0;
  /// The swept value first (when any), then each dispersion's draw, in the file's order.
  std::vector<std::pair<std::string, ScenarioValue>> parameters;
};

std::uint64_t splitmix64(std::uint64_t x);

/// Run `index` of `campaign` (0 <= index < total_runs()).
RunSpec run_spec(const Campaign& campaign, std::int64_t index);

/// The scenario of a run: the base with `set`, then the run's parameters, and its seed. Errors
/// name the key.
core::Result<sim::CampaignScenario> scenario_for(const Campaign& campaign, const RunSpec& run);

/// Every key of the campaign applied alone to the base scenario and read by its reader: each set
/// value, each swept value, each dispersion's choices or extremes (normal: mean -/+ 3 sigma;
/// uniform: min and max). Errors name where the value was written and the scenario's complaint.
core::Result<bool> check_against_scenario(const Campaign& campaign);

/// The base scenario with the campaign's `set` applied (recorded in the results store).
core::Result<sim::CampaignScenario> base_scenario(const Campaign& campaign);

}  // namespace visors::mc
