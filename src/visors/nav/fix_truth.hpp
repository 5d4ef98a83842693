#pragma once
// Scoring a fixed solution against the truth (ground tools: `visors nav` and the closed loop's
// navigation score; header-only, it only reads the filter): a full fix is wrong when any of the
// epoch's double differences of the fixed SDCP ambiguities differs from the truth's by more than
// half a cycle.

#include <cmath>

#include "visors/nav/cdgps_filter.hpp"

namespace visors::nav {

/// `true_sd(prn)`: the true single-difference ambiguity of `prn` (OSC minus DSC, with the
/// receivers' phase offsets) [cycles], NaN when unknown (that double difference is then not
/// judged). Uses the report's double differences and the filter's fixed solution.
template <class TrueSd>
bool wrong_fix(const CdgpsFilter& filter, const CdgpsEpochReport& report, const TrueSd& true_sd) {
  const auto slots = filter.sdcp_slots();
  const auto state_of = [&slots](int prn) {
    for (int i = 0; i < slots.count; ++i) {
      if (slots.prn[static_cast<std::size_t>(i)] == prn) return slots.state[static_cast<std::size_t>(i)];
    }
    return -1;
  };
  const int reference = report.dd_prns[0];
  const int reference_state = state_of(reference);
  for (int j = 1; j <= report.double_differences; ++j) {
    const int prn = report.dd_prns[static_cast<std::size_t>(j)];
    const int state = state_of(prn);
    if (state < 0 || reference_state < 0) continue;
    const double estimated = filter.x_fixed()(state) - filter.x_fixed()(reference_state);
    const double expected = true_sd(prn) - true_sd(reference);
    if (std::isfinite(expected) && std::abs(estimated - expected) > 0.5) return true;
  }
  return false;
}

}  // namespace visors::nav
