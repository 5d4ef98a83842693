#pragma once
// The scores of `visors nav` against the run's truth: per epoch (score) and over the replay
// (summarise: the acceptance figures).

#include <nlohmann/json.hpp>

#include "nav/cdgps_filter.hpp"
#include "nav/nav_inputs.hpp"
#include "nav/nav_replay.hpp"

namespace visors::nav_app {

/// The epoch's errors of the filter's solution (the fixed one when the report applied a fix) at
/// t_s [s after the scenario start], the filter running on `local`.
EpochScore score(const nav::CdgpsFilter& filter, const nav::CdgpsEpochReport& report, const RunInputs& in, double t_s,
                 nav::Craft local);

/// The replay's statistics (nav_command.hpp: the summary's fields).
nlohmann::json summarise(const Replay& replay);

}  // namespace visors::nav_app
