#include "visors/nav/ambiguity_acceptance.hpp"

#include <algorithm>
#include <cmath>

namespace visors::nav {
namespace {

bool uses_success_rate(AcceptanceRule rule) { return rule != AcceptanceRule::kRatio; }
bool uses_ratio(AcceptanceRule rule) { return rule != AcceptanceRule::kSuccessRate; }

AmbiguityFix float_solution(FloatReason reason, IlsStatus status, double success_rate) {
  AmbiguityFix fix;
  fix.outcome = FixOutcome::kFloat;
  fix.reason = reason;
  fix.status = status;
  fix.fixed = 0;
  fix.success_rate = success_rate;
  return fix;
}

// How many trailing decorrelated combinations to search: all, a partial subset, or 0 (float).
Eigen::Index combinations_to_search(const IntegerLeastSquares& ils, Eigen::Index n, const AcceptanceSettings& s) {
  if (!uses_success_rate(s.rule) || ils.success_rate_bootstrap() >= s.min_success_rate) return n;
  if (!s.partial) return 0;
  const Eigen::Index k = ils.partial_fix_size(s.min_success_rate);
  return k >= std::max<Eigen::Index>(1, s.min_partial) ? k : 0;
}

}  // namespace

core::Status validate(const AcceptanceSettings& s) {
  if (!(s.min_success_rate > 0.0 && s.min_success_rate < 1.0)) {
    return core::Status{core::Problem::kOutOfRange, "min_success_rate", "must be in (0, 1)"};
  }
  if (!(s.min_ratio >= 1.0) || !std::isfinite(s.min_ratio)) return core::Status{core::Problem::kOutOfRange, "min_ratio", "must be a finite number >= 1"};
  if (s.min_partial < 1) return core::Status{core::Problem::kOutOfRange, "min_partial", "must be >= 1"};
  return {};
}

std::string_view to_string(FixOutcome outcome) {
  switch (outcome) {
    case FixOutcome::kFixed: return "fixed";
    case FixOutcome::kPartial: return "partial";
    case FixOutcome::kFloat: return "float";
  }
  return "unknown";
}

std::string_view to_string(FloatReason reason) {
  switch (reason) {
    case FloatReason::kNone: return "none";
    case FloatReason::kInvalidInput: return "invalid_input";
    case FloatReason::kLowSuccessRate: return "low_success_rate";
    case FloatReason::kLowRatio: return "low_ratio";
    case FloatReason::kSearchLimit: return "search_limit";
  }
  return "unknown";
}

AmbiguityFix resolve_ambiguities(IntegerLeastSquares& ils, const Eigen::Ref<const Eigen::VectorXd>& a,
                                 const Eigen::Ref<const Eigen::MatrixXd>& Q, const AcceptanceSettings& settings) {
  const IlsStatus decorrelated = ils.decorrelate(a, Q);
  if (decorrelated != IlsStatus::kOk) return float_solution(FloatReason::kInvalidInput, decorrelated, 0.0);
  const Eigen::Index n = a.size();
  const Eigen::Index k = combinations_to_search(ils, n, settings);
  if (k == 0) return float_solution(FloatReason::kLowSuccessRate, IlsStatus::kOk, ils.success_rate_bootstrap());
  const IlsStatus searched = ils.search(k);
  const IlsSolution& solution = ils.solution();
  if (searched != IlsStatus::kOk) return float_solution(FloatReason::kSearchLimit, searched, solution.success_rate);
  AmbiguityFix fix;
  fix.status = IlsStatus::kOk;
  fix.success_rate = solution.success_rate;
  fix.ratio = solution.ratio;
  if (uses_ratio(settings.rule) && !(solution.ratio >= settings.min_ratio)) {
    fix.outcome = FixOutcome::kFloat;
    fix.reason = FloatReason::kLowRatio;
    return fix;
  }
  fix.outcome = k == n ? FixOutcome::kFixed : FixOutcome::kPartial;
  fix.reason = FloatReason::kNone;
  fix.fixed = k;
  return fix;
}

}  // namespace visors::nav
