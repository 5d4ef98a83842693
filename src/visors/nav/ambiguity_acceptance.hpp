#pragma once
// Acceptance of an integer solution (docs/algorithms/ambiguity-resolution.md#acceptance): which
// ambiguities to fix, and
// whether to fix them at all.
//
// - Success-rate test (model driven, Teunissen 1998/1999): fix only when the bootstrapped success
//   rate of the decorrelated problem reaches min_success_rate = P0. Integer least squares succeeds
//   at least as often as bootstrapping, so the probability of fixing a wrong integer vector is at
//   most 1 - P0 per attempt when Q is right. This is the rule's promise, checked by simulation in
//   tests/nav/test_acceptance_statistics.cpp.
// - Ratio test (data driven, Euler & Schaffrin 1991; RTKLIB's default threshold 3.0): fix only
//   when s_2 / s_1 >= min_ratio. A constant threshold promises no failure rate (its failure rate
//   depends on n and on Q; the fixed-failure-rate ratio test of Verhagen & Teunissen 2013 derives
//   the threshold from simulated tables, not implemented here); it rejects float solutions whose
//   best and second-best integers are nearly as likely, which the success rate cannot see.
// - Both (default): the success-rate promise holds and ambiguous cases are still refused.
// - Partial fixing (Teunissen, Joosten & Tiberius 1999): when the whole set falls short of P0, fix
//   the largest trailing subset of decorrelated combinations whose success rate reaches P0 (the
//   best determined ones; their LtDL is the trailing block of the full one), with the same ratio
//   test on that subset. The fixed quantities are integer combinations Z_k' a of the ambiguities.

#include <string_view>

#include <Eigen/Core>

#include "visors/core/status.hpp"
#include "visors/nav/integer_least_squares.hpp"

namespace visors::nav {

enum class AcceptanceRule { kSuccessRate, kRatio, kSuccessRateAndRatio };

struct AcceptanceSettings {
  AcceptanceRule rule = AcceptanceRule::kSuccessRateAndRatio;
  double min_success_rate = 0.999;  // P0, bootstrapped success rate required, in (0, 1) [-]
  double min_ratio = 3.0;           // c, s_2 / s_1 required, >= 1 [-]
  bool partial = true;              // partial fixing when the whole set falls short of P0
  int min_partial = 4;              // fewest combinations a partial fix may have, >= 1
};

/// Each value checked; the error names the field.
core::Status validate(const AcceptanceSettings& settings);

enum class FixOutcome { kFixed, kPartial, kFloat };
enum class FloatReason { kNone, kInvalidInput, kLowSuccessRate, kLowRatio, kSearchLimit };

/// "fixed", "partial", "float"; "none", "invalid_input", "low_success_rate", "low_ratio",
/// "search_limit".
std::string_view to_string(FixOutcome outcome);
std::string_view to_string(FloatReason reason);

struct AmbiguityFix {
  FixOutcome outcome = FixOutcome::kFloat;
  FloatReason reason = FloatReason::kInvalidInput;
  IlsStatus status = IlsStatus::kOk;  // of decorrelate() / search()
  Eigen::Index fixed = 0;             // combinations fixed (n when kFixed)
  double success_rate = 0.0;          // bootstrapped, of the combinations searched (all n if none)
  double ratio = 0.0;                 // s_2 / s_1 of the combinations searched, 0 when not searched
};

/// Decorrelates (a, Q), chooses the combinations to fix and searches them with `ils` (whose
/// settings must ask for 2 or more candidates when the rule has a ratio test). After kFixed or
/// kPartial, ils.solution() holds the integers (z, and a when kFixed) and ils.decorrelated() the
/// combinations Z(:, n-k..). Allocates nothing.
AmbiguityFix resolve_ambiguities(IntegerLeastSquares& ils, const Eigen::Ref<const Eigen::VectorXd>& a,
                                 const Eigen::Ref<const Eigen::MatrixXd>& Q, const AcceptanceSettings& settings);

}  // namespace visors::nav
