#include "nav/integer_least_squares.hpp"

#include <cassert>
#include <cmath>
#include <limits>
#include <string>

#include "nav/bootstrap.hpp"
#include "nav/mlambda_search.hpp"

namespace visors::nav {

using Eigen::Index;

struct IntegerLeastSquares::Workspace {
  Decorrelation decorrelation;
  DecorrelationWorkspace decorrelation_workspace;
  SearchWorkspace search;
  AmbiguityVector a_integer;    // round(a) [cycles]
  AmbiguityVector a_fraction;   // a - round(a) [cycles]
  AmbiguityVector z_fraction;   // Z' (a - round(a)): what the search works on [cycles]
  AmbiguityVector z_integer;    // Z' round(a), exact integers
  AmbiguityVector z_hat;        // Z' a = z_fraction + z_integer [cycles]
  CandidateMatrix z_found;      // candidates of the fractional problem
  IlsSolution solution;
  bool decorrelated = false;
};

core::Result<IlsSettings> validate(const IlsSettings& s) {
  if (s.candidates < 1 || s.candidates > kMaxCandidates) {
    return core::Error{"candidates", "must be an integer in [1, " + std::to_string(kMaxCandidates) + "]"};
  }
  if (s.max_search_steps < 1) return core::Error{"max_search_steps", "must be >= 1"};
  if (s.max_permutations < 0) return core::Error{"max_permutations", "must be >= 0"};
  if (!(s.symmetry_tolerance >= 0.0) || !std::isfinite(s.symmetry_tolerance)) {
    return core::Error{"symmetry_tolerance", "must be a finite number >= 0"};
  }
  return s;
}

std::string_view to_string(IlsStatus status) {
  switch (status) {
    case IlsStatus::kOk: return "ok";
    case IlsStatus::kEmpty: return "empty";
    case IlsStatus::kTooManyAmbiguities: return "too_many_ambiguities";
    case IlsStatus::kSizeMismatch: return "size_mismatch";
    case IlsStatus::kNotFinite: return "not_finite";
    case IlsStatus::kNotSymmetric: return "not_symmetric";
    case IlsStatus::kNotPositiveDefinite: return "not_positive_definite";
    case IlsStatus::kSearchLimit: return "search_limit";
  }
  return "unknown";
}

core::Result<IntegerLeastSquares> IntegerLeastSquares::create(const IlsSettings& settings) {
  auto checked = validate(settings);
  if (!checked) return checked.error();
  return IntegerLeastSquares(settings, std::make_unique<Workspace>());
}

IntegerLeastSquares::IntegerLeastSquares(const IlsSettings& settings, std::unique_ptr<Workspace> workspace)
    : settings_(settings), w_(std::move(workspace)) {}
IntegerLeastSquares::IntegerLeastSquares(IntegerLeastSquares&&) noexcept = default;
IntegerLeastSquares& IntegerLeastSquares::operator=(IntegerLeastSquares&&) noexcept = default;
IntegerLeastSquares::~IntegerLeastSquares() = default;

IlsStatus IntegerLeastSquares::validate_input(const Eigen::Ref<const Eigen::VectorXd>& a,
                                              const Eigen::Ref<const Eigen::MatrixXd>& Q) const {
  const Index n = a.size();
  if (n == 0) return IlsStatus::kEmpty;
  if (Q.rows() != Q.cols() || Q.rows() != n) return IlsStatus::kSizeMismatch;
  if (n > kMaxAmbiguities) return IlsStatus::kTooManyAmbiguities;
  if (!a.allFinite() || !Q.allFinite()) return IlsStatus::kNotFinite;
  for (Index j = 0; j < n; ++j) {
    if (!(Q(j, j) > 0.0)) return IlsStatus::kNotPositiveDefinite;
    for (Index i = j + 1; i < n; ++i) {
      const double scale = std::sqrt(Q(i, i) * Q(j, j));
      if (std::abs(Q(i, j) - Q(j, i)) > settings_.symmetry_tolerance * scale) return IlsStatus::kNotSymmetric;
    }
  }
  return IlsStatus::kOk;
}

IlsStatus IntegerLeastSquares::decorrelate(const Eigen::Ref<const Eigen::VectorXd>& a,
                                           const Eigen::Ref<const Eigen::MatrixXd>& Q) {
  Workspace& w = *w_;
  w.decorrelated = false;
  if (const IlsStatus status = validate_input(a, Q); status != IlsStatus::kOk) return status;
  if (!nav::decorrelate(Q, settings_.max_permutations, w.decorrelation, w.decorrelation_workspace)) {
    return IlsStatus::kNotPositiveDefinite;
  }
  const Index n = a.size();
  const auto Z = w.decorrelation.Z.topLeftCorner(n, n);
  w.a_integer = a.array().round();
  w.a_fraction = a - w.a_integer;
  w.z_fraction.noalias() = Z.transpose() * w.a_fraction;
  w.z_integer.noalias() = Z.transpose() * w.a_integer;
  w.z_hat = w.z_fraction + w.z_integer;
  w.decorrelated = true;
  return IlsStatus::kOk;
}

DecorrelatedAmbiguities IntegerLeastSquares::decorrelated() const { return {w_->decorrelation, w_->z_hat}; }

double IntegerLeastSquares::success_rate_bootstrap() const {
  return bootstrap_success_rate(w_->decorrelation.d.head(w_->decorrelation.n));
}

Index IntegerLeastSquares::partial_fix_size(double min_success_rate) const {
  return nav::partial_fix_size(w_->decorrelation.d.head(w_->decorrelation.n), min_success_rate);
}

IlsStatus IntegerLeastSquares::search(Index k) {
  Workspace& w = *w_;
  const Decorrelation& dc = w.decorrelation;
  const Index n = dc.n;
  assert(w.decorrelated && k >= 1 && k <= n);
  const Index first = n - k;
  IlsSolution& out = w.solution;
  out.n = n;
  out.fixed = k;
  out.found = 0;
  const Index m = settings_.candidates;
  const SearchOutcome outcome =
      search_integer_candidates(dc.L.block(first, first, k, k), dc.d.segment(first, k), w.z_fraction.segment(first, k), m,
                                settings_.max_search_steps, w.search, w.z_found, out.sqnorm);
  out.search_steps = outcome.steps;
  out.success_rate = bootstrap_success_rate(dc.d.segment(first, k));
  if (outcome.status == SearchStatus::kStepLimit) return IlsStatus::kSearchLimit;
  out.found = outcome.found;
  out.z = w.z_found.topLeftCorner(k, out.found).colwise() + w.z_integer.segment(first, k);
  out.ratio = out.found < 2 ? 0.0
              : out.sqnorm(0) > 0.0 ? out.sqnorm(1) / out.sqnorm(0)
                                    : std::numeric_limits<double>::infinity();
  if (k == n) back_transform();
  return IlsStatus::kOk;
}

// a = Z^-T z, with the exact integer Z^-T of the reduction; the result is integer up to round-off
// of the products (exact below 2^53), so it is rounded.
void IntegerLeastSquares::back_transform() {
  Workspace& w = *w_;
  const Index n = w.decorrelation.n;
  IlsSolution& out = w.solution;
  out.a.resize(n, out.found);
  out.a.noalias() = w.decorrelation.Z_inv_t.topLeftCorner(n, n) * w.z_found.topLeftCorner(n, out.found);
  out.a = out.a.array().round();
  out.a.colwise() += w.a_integer;
}

IlsStatus IntegerLeastSquares::resolve(const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& Q) {
  if (const IlsStatus status = decorrelate(a, Q); status != IlsStatus::kOk) return status;
  return search(w_->decorrelation.n);
}

const IlsSolution& IntegerLeastSquares::solution() const { return w_->solution; }

}  // namespace visors::nav
