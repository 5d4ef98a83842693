#include "visors/nav/integer_least_squares.hpp"

#include <cassert>
#include <cmath>
#include <limits>

#include "visors/nav/bootstrap.hpp"
#include "visors/nav/mlambda_search.hpp"

namespace visors::nav {

using Eigen::Index;

struct IntegerLeastSquares::Workspace {
  Decorrelation decorrelation;
  DecorrelationWorkspace decorrelation_workspace;
  SearchWorkspace search;
  AmbiguityVector a_integer;    // round(a) [cycles]
  // Columns: Z' (a - round(a)), what the search works on [cycles], and Z' round(a), exact integers.
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::ColMajor, kMaxAmbiguities, 2> z_parts;
  AmbiguityVector z_hat;        // Z' a = the sum of the columns of z_parts [cycles]
  CandidateMatrix z_found;      // candidates of the fractional problem
  IlsSolution solution;
  AmbiguityMatrix Z;            // formed on request (transformation())
  bool decorrelated = false;
  bool Z_formed = false;
};

core::Status validate(const IlsSettings& s) {
  if (s.candidates < 1 || s.candidates > kMaxCandidates) {
    return core::Status{core::Problem::kOutOfRange, "candidates", core::in_range_text<1, kMaxCandidates>()};
  }
  if (s.max_search_steps < 1) return core::Status{core::Problem::kOutOfRange, "max_search_steps", "must be >= 1"};
  if (s.max_permutations < 0) return core::Status{core::Problem::kOutOfRange, "max_permutations", "must be >= 0"};
  if (!(s.symmetry_tolerance >= 0.0) || !std::isfinite(s.symmetry_tolerance)) {
    return core::Status{core::Problem::kOutOfRange, "symmetry_tolerance", "must be a finite number >= 0"};
  }
  return {};
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
  }
  // |Q_ij - Q_ji| <= tol sqrt(Q_ii Q_jj), squared (no square root per pair).
  const double tol2 = settings_.symmetry_tolerance * settings_.symmetry_tolerance;
  for (Index j = 0; j < n; ++j) {
    for (Index i = j + 1; i < n; ++i) {
      const double asymmetry = Q(i, j) - Q(j, i);
      if (asymmetry * asymmetry > tol2 * Q(i, i) * Q(j, j)) return IlsStatus::kNotSymmetric;
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
  w.a_integer = a.array().round();
  w.z_parts.resize(a.size(), 2);
  w.z_parts.col(0) = a - w.a_integer;
  w.z_parts.col(1) = w.a_integer;
  w.decorrelation.transform.apply_transpose(w.z_parts);
  w.z_hat = w.z_parts.col(0) + w.z_parts.col(1);
  w.decorrelated = true;
  w.Z_formed = false;
  return IlsStatus::kOk;
}

DecorrelatedAmbiguities IntegerLeastSquares::decorrelated() const { return {w_->decorrelation, w_->z_hat}; }

const AmbiguityMatrix& IntegerLeastSquares::transformation() const {
  Workspace& w = *w_;
  assert(w.decorrelated);
  if (!w.Z_formed) {
    w.decorrelation.transform.matrix(w.Z);
    w.Z_formed = true;
  }
  return w.Z;
}

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
      search_integer_candidates(dc.L.block(first, first, k, k), dc.d.segment(first, k), w.z_parts.col(0).segment(first, k), m,
                                settings_.max_search_steps, w.search, w.z_found, out.sqnorm);
  out.search_steps = outcome.steps;
  out.success_rate = bootstrap_success_rate(dc.d.segment(first, k));
  if (outcome.status == SearchStatus::kStepLimit) return IlsStatus::kSearchLimit;
  out.found = outcome.found;
  out.z = w.z_found.topLeftCorner(k, out.found).colwise() + w.z_parts.col(1).segment(first, k);
  out.ratio = out.found < 2 ? 0.0
              : out.sqnorm(0) > 0.0 ? out.sqnorm(1) / out.sqnorm(0)
                                    : std::numeric_limits<double>::infinity();
  if (k == n) back_transform();
  return IlsStatus::kOk;
}

// a = Z^-T z by the reduction's integer operations in reverse: exact for integer z (below 2^53).
void IntegerLeastSquares::back_transform() {
  Workspace& w = *w_;
  const Index n = w.decorrelation.n;
  IlsSolution& out = w.solution;
  out.a = w.z_found.topLeftCorner(n, out.found);
  w.decorrelation.transform.apply_inverse_transpose(out.a);
  out.a.colwise() += w.a_integer;
}

IlsStatus IntegerLeastSquares::resolve(const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& Q) {
  if (const IlsStatus status = decorrelate(a, Q); status != IlsStatus::kOk) return status;
  return search(w_->decorrelation.n);
}

const IlsSolution& IntegerLeastSquares::solution() const { return w_->solution; }

}  // namespace visors::nav
