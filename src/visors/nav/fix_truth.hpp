#pragma once
// Scoring an applied fix against the truth (ground tools: `visors nav` and the closed loop's
// navigation score; header-only, it only reads the filter's report and fixed solution).
// - A full fix is wrong when any of the epoch's double differences of the fixed SDCP ambiguities
//   differs from the truth's by more than half a cycle.
// - A partial fix constrains integer combinations of the double differences, not single ones:
//   its unfixed directions keep their float errors (a cycle or more at the first fixes), so it
//   is wrong when any of its fixed combinations (CdgpsEpochReport::fixed_combinations) differs
//   from the same combination of the true double differences by more than half a cycle. The true
//   double differences are integers (the receivers' phase offsets cancel), so a right combination
//   is exact to the truth's rounding.

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "visors/nav/cdgps_filter.hpp"

namespace visors::nav {

/// True when the integer `fixed` [cycles] differs by more than half a cycle from the combination
/// sum over j = first..last of coefficient(j) true_dd(j) of the true double differences; a NaN
/// in one it weighs (a satellite the truth lacks) leaves it unjudged (false).
template <class Coefficient, class TrueDd>
bool wrong_combination(std::int64_t fixed, int first, int last, const Coefficient& coefficient, const TrueDd& true_dd) {
  double expected = 0.0;
  for (int j = first; j <= last; ++j) {
    const std::int32_t c = coefficient(j);
    if (c != 0) expected += static_cast<double>(c) * true_dd(j);
  }
  return std::isfinite(expected) && std::abs(static_cast<double>(fixed) - expected) > 0.5;
}

/// `true_sd(prn)`: the true single-difference ambiguity of `prn` (OSC minus DSC, with the
/// receivers' phase offsets) [cycles], NaN when unknown (a double difference or combination that
/// needs it is then not judged). A full fix is judged on the filter's fixed solution, a partial
/// one on the report's combinations (file comment).
template <class TrueSd>
bool wrong_fix(const CdgpsFilter& filter, const CdgpsEpochReport& report, const TrueSd& true_sd) {
  const int reference = report.dd_prns[0];
  const auto true_dd = [&](int j) { return true_sd(report.dd_prns[static_cast<std::size_t>(j)]) - true_sd(reference); };
  if (report.fix.outcome == FixOutcome::kPartial) {
    for (int i = 0; i < report.fixed_combinations; ++i) {
      const auto& coefficients = report.combination_coefficients[static_cast<std::size_t>(i)];
      const auto coefficient = [&coefficients](int j) { return coefficients[static_cast<std::size_t>(j)]; };
      if (wrong_combination(report.combination_integers[static_cast<std::size_t>(i)], 1, report.double_differences, coefficient, true_dd)) {
        return true;
      }
    }
    return false;
  }
  const auto slots = filter.sdcp_slots();
  const auto state_of = [&slots](int prn) {
    for (int i = 0; i < slots.count; ++i) {
      if (slots.prn[static_cast<std::size_t>(i)] == prn) return slots.state[static_cast<std::size_t>(i)];
    }
    return -1;
  };
  const int reference_state = state_of(reference);
  for (int j = 1; j <= report.double_differences; ++j) {
    const int state = state_of(report.dd_prns[static_cast<std::size_t>(j)]);
    if (state < 0 || reference_state < 0) continue;
    const double estimated = filter.x_fixed()(state) - filter.x_fixed()(reference_state);
    const double expected = true_dd(j);
    if (std::isfinite(expected) && std::abs(estimated - expected) > 0.5) return true;
  }
  return false;
}

}  // namespace visors::nav
