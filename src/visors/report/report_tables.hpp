#pragma once
// The tables of the run report: the summary box, the delta-v budget beside the paper's, the
// observations and the event log. Each is an HTML fragment with a stable id; an empty list
// renders as "none".

#include <cstddef>
#include <string>

#include "visors/report/run_data.hpp"

namespace visors::report {

/// Events beyond this many are counted, not listed (a long run logs every maneuver piece).
inline constexpr std::size_t kMaxEventsListed = 200;
/// The mission's requirement on the fraction of successful observations.
inline constexpr double kRequiredSuccessRate = 0.20;

std::string summary_box(const RunData& run);
std::string delta_v_table(const RunData& run);
std::string observation_table(const RunData& run);
/// Each attempt's error budget at its worst lateral sample (lateral x, y and focus of every term;
/// docs/run-directory.md), when observations.csv has it.
std::string budget_table(const RunData& run);
std::string event_table(const RunData& run);

}  // namespace visors::report
