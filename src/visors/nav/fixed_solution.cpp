#include "visors/nav/fixed_solution.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/Cholesky>

namespace visors::nav {

using Eigen::Index;
using Status = FixedSolutionUpdate::Status;

namespace {

// A squared Cholesky pivot below this fraction of the largest diagonal entry of S counts as
// singular: the solve would keep fewer than ~3 of 16 digits (same rule as optim/separable_kkt).
// Redundant fixed combinations with s = 0 give pivots at the round-off level, ~1e-16 relative.
constexpr double kRelativePivot = 1e-13;

}  // namespace

core::Result<FixedSolutionUpdate> FixedSolutionUpdate::create(Index max_states, Index max_constraints) {
  if (max_states < 1) return core::Error{"max_states", "must be >= 1"};
  if (max_constraints < 1 || max_constraints > kMaxAmbiguities) {
    return core::Error{"max_constraints", "must be in [1, " + std::to_string(kMaxAmbiguities) + "]"};
  }
  return FixedSolutionUpdate(max_states, max_constraints);
}

FixedSolutionUpdate::FixedSolutionUpdate(Index max_states, Index max_constraints)
    : max_states_(max_states),
      max_constraints_(max_constraints),
      S_(Eigen::MatrixXd::Zero(max_constraints, max_constraints)),
      W_(Eigen::MatrixXd::Zero(max_constraints, max_states)),
      v_(Eigen::VectorXd::Zero(max_constraints)),
      G_(Eigen::MatrixXd::Zero(max_states, max_constraints)),
      K_(Eigen::MatrixXd::Zero(max_states, max_constraints)) {}

std::string_view to_string(Status status) {
  switch (status) {
    case Status::kOk: return "ok";
    case Status::kSizeMismatch: return "size_mismatch";
    case Status::kOutOfCapacity: return "out_of_capacity";
    case Status::kNotFinite: return "not_finite";
    case Status::kNegativeVariance: return "negative_variance";
    case Status::kNotPositiveDefinite: return "not_positive_definite";
  }
  return "unknown";
}

Status FixedSolutionUpdate::check(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::MatrixXd>& P,
                                  const Eigen::Ref<const Eigen::MatrixXd>& C, const Eigen::Ref<const Eigen::VectorXd>& z,
                                  double variance) const {
  const Index n = x.size();
  const Index k = C.rows();
  if (P.rows() != n || P.cols() != n || C.cols() != n || z.size() != k) return Status::kSizeMismatch;
  if (n > max_states_ || k > max_constraints_) return Status::kOutOfCapacity;
  if (!std::isfinite(variance) || !x.allFinite() || !P.allFinite() || !C.allFinite() || !z.allFinite()) {
    return Status::kNotFinite;
  }
  if (variance < 0.0) return Status::kNegativeVariance;
  return Status::kOk;
}

// In-place Cholesky S = L L' in the lower triangle of S_'s k x k corner (Eigen's LLT on a Ref
// works in the referenced storage: nothing allocated). Reads the lower triangle only.
bool FixedSolutionUpdate::factor(Index k) {
  Eigen::Ref<Eigen::MatrixXd> s = S_.topLeftCorner(k, k);
  const double largest = s.diagonal().maxCoeff();
  if (!(largest > 0.0)) return false;
  const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(s);
  if (llt.info() != Eigen::Success) return false;
  return s.diagonal().cwiseAbs2().minCoeff() > kRelativePivot * largest;
}

// The columns [first, first + width) of C holding all its non-zero entries (width 0 for C = 0).
// An ambiguity fix touches only the ambiguity states: C P and C x need only those rows of P and x.
std::pair<Index, Index> FixedSolutionUpdate::column_span(const Eigen::Ref<const Eigen::MatrixXd>& C) {
  Index first = C.cols(), last = -1;
  for (Index j = 0; j < C.cols(); ++j) {
    if ((C.col(j).array() == 0.0).all()) continue;
    first = std::min(first, j);
    last = j;
  }
  return last < 0 ? std::pair<Index, Index>{0, 0} : std::pair<Index, Index>{first, last - first + 1};
}

// The update's common part for k = C.rows() >= 1: W = C P (k x n), S = C P C' + s I factored
// (L in S_), v = z - C x; kNotPositiveDefinite when S is not numerically positive definite.
Status FixedSolutionUpdate::innovation_system(const Eigen::Ref<const Eigen::VectorXd>& x,
                                              const Eigen::Ref<const Eigen::MatrixXd>& P,
                                              const Eigen::Ref<const Eigen::MatrixXd>& C,
                                              const Eigen::Ref<const Eigen::VectorXd>& z, double variance) {
  const Index k = C.rows();
  const auto [first, width] = column_span(C);
  const auto c = C.middleCols(first, width);
  auto W = W_.topLeftCorner(k, x.size());
  W.noalias() = c * P.middleRows(first, width);  // = C P = (P C')' for the symmetric P
  S_.topLeftCorner(k, k).noalias() = W.middleCols(first, width) * c.transpose();
  S_.topLeftCorner(k, k).diagonal().array() += variance;
  v_.head(k) = z;
  v_.head(k).noalias() -= c * x.segment(first, width);
  return factor(k) ? Status::kOk : Status::kNotPositiveDefinite;
}

Status FixedSolutionUpdate::apply(Eigen::Ref<Eigen::VectorXd> x, Eigen::Ref<Eigen::MatrixXd> P,
                                  const Eigen::Ref<const Eigen::MatrixXd>& C, const Eigen::Ref<const Eigen::VectorXd>& z,
                                  double variance) {
  if (const Status status = check(x, P, C, z, variance); status != Status::kOk) return status;
  const Index k = C.rows();
  if (k == 0) return Status::kOk;
  if (const Status status = innovation_system(x, P, C, z, variance); status != Status::kOk) return status;
  auto W = W_.topLeftCorner(k, x.size());
  auto v = v_.head(k);
  const auto L = S_.topLeftCorner(k, k).triangularView<Eigen::Lower>();
  L.solveInPlace(W);  // W = L^-1 C P
  L.solveInPlace(v);  // v = L^-1 (z - C x)
  if (!W.allFinite() || !v.allFinite()) return Status::kNotFinite;  // overflow of a finite input
  x.noalias() += W.transpose() * v;
  // P - W' W on the lower triangle (half the products of the full one), mirrored: P+ exactly
  // symmetric whatever round-off asymmetry the input P had.
  P.selfadjointView<Eigen::Lower>().rankUpdate(W.transpose(), -1.0);
  P.triangularView<Eigen::StrictlyUpper>() = P.transpose();
  return Status::kOk;
}

Status FixedSolutionUpdate::apply(Eigen::Ref<Eigen::VectorXd> x, Eigen::Ref<Eigen::MatrixXd> P,
                                  const Eigen::Ref<const Eigen::MatrixXd>& C, const Eigen::Ref<const Eigen::VectorXd>& z,
                                  double variance, const Eigen::Ref<const Eigen::VectorXd>& gain_mask) {
  if (gain_mask.size() != x.size()) return Status::kSizeMismatch;
  if (!gain_mask.allFinite()) return Status::kNotFinite;
  if ((gain_mask.array() == 1.0).all()) return apply(x, P, C, z, variance);
  if (const Status status = check(x, P, C, z, variance); status != Status::kOk) return status;
  const Index n = x.size();
  const Index k = C.rows();
  if (k == 0) return Status::kOk;
  if (const Status status = innovation_system(x, P, C, z, variance); status != Status::kOk) return status;
  auto G = G_.topLeftCorner(n, k);
  auto K = K_.topLeftCorner(n, k);
  G = W_.topLeftCorner(k, n).transpose();  // P C'
  const auto L = S_.topLeftCorner(k, k).triangularView<Eigen::Lower>();
  K = G;
  L.solveInPlace(K.transpose());              // K' <- L^-1 G'
  L.transpose().solveInPlace(K.transpose());  // K' <- L^-T L^-1 G' = S^-1 G'
  K.array().colwise() *= gain_mask.array();
  if (!K.allFinite()) return Status::kNotFinite;
  x.noalias() += K * v_.head(k);
  // P - K G' - G K' + K S K', with K S K' = (K L)(K L)'.
  P.noalias() -= K * G.transpose();
  P.noalias() -= G * K.transpose();
  G.noalias() = K * S_.topLeftCorner(k, k).triangularView<Eigen::Lower>();  // K L
  P.noalias() += G * G.transpose();
  P.triangularView<Eigen::StrictlyUpper>() = P.transpose();  // exactly symmetric
  return Status::kOk;
}

Index fixed_constraints(const AmbiguityFix& fix, const IntegerLeastSquares& ils, const DoubleDifferenceAmbiguities& dd,
                        Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> z) {
  if (fix.outcome == FixOutcome::kFloat) return 0;
  const IlsSolution& solution = ils.solution();
  const Index n = dd.size();
  const Index k = solution.fixed;
  const bool consistent =
      fix.fixed == k && k >= 1 && solution.found >= 1 && solution.n == n && ils.decorrelated().decorrelation.n == n;
  if (!consistent || C.cols() != dd.states() || C.rows() < k || z.size() < k) return 0;
  const AmbiguityMatrix& Z = ils.transformation();
  // Row j of C is Z(:, first + j)' G = sum_r Z(r, first + j) (e_{state r} - e_{reference r})'.
  const Index first = n - k;
  C.topRows(k).setZero();
  for (Index j = 0; j < k; ++j) {
    for (Index r = 0; r < n; ++r) {
      const double coefficient = Z(r, first + j);
      C(j, dd.state_of(r)) += coefficient;
      C(j, dd.reference_of(r)) -= coefficient;
    }
  }
  z.head(k) = solution.z.col(0);
  return k;
}

}  // namespace visors::nav
