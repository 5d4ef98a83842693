#pragma once
// Integer least-squares search for the m best integer vectors in the decorrelated space: the
// shrinking-ellipsoid Schnorr-Euchner enumeration of MLAMBDA (Chang, Yang & Zhou 2005, J. Geodesy
// 79:552-565, sec. 4; docs/algorithms/ambiguity-resolution.md#mlambda-search).
//
// Given Q_z = L' diag(d) L (L unit lower triangular, factorised from the back) and the float
// z_hat, it minimises sum_i (z_hat_{i|I} - z_i)^2 / d_i = (z_hat - z)' Q_z^-1 (z_hat - z), where
// z_hat_{i|I} = z_hat_i + sum_{j>i} (z_j - z_hat_{j|J}) L(j,i) is the estimate of z_i conditioned on
// the integers chosen for i+1..n-1. Levels are visited from n-1 down to 0, each level's integers
// in zig-zag order around its conditional estimate (nearest first), a branch is abandoned as soon
// as its partial distance reaches the m-th best distance found so far, and that bound shrinks as
// better vectors are found. The first full vector reached is the bootstrapped solution.
//
// Bounded work: every visit of a level counts one step; at max_steps the search stops with
// kStepLimit and its candidates must not be used (they may not be the best).

#include <Eigen/Core>

#include "visors/nav/ambiguity_capacity.hpp"

namespace visors::nav {

enum class SearchStatus { kOk, kStepLimit };

struct SearchWorkspace {
  AmbiguityMatrix L;          // L of the searched block, contiguous
  // partial_sums(j, k) = sum over i >= j of (z_i - z_hat_{i|I}) L(i, k), j = k+1..n (row n: zero)
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxAmbiguities + 1, kMaxAmbiguities> partial_sums;
  Eigen::Matrix<Eigen::Index, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxAmbiguities, 1> begin;  // see the search
  AmbiguityVector inv_d;      // 1 / d [1/cycles^2]
  AmbiguityVector z_hat;      // float ambiguities of the searched block [cycles]
  AmbiguityVector distance;   // partial distance of the levels above each level
  AmbiguityVector estimate;   // conditional estimate z_hat_{k|K}
  AmbiguityVector z;          // current integer at each level
  AmbiguityVector step;       // next zig-zag increment at each level
};

struct SearchOutcome {
  SearchStatus status = SearchStatus::kOk;
  Eigen::Index found = 0;  // candidates stored (< m only when fewer integer vectors exist: never)
  long steps = 0;
};

/// Searches the m (1..kMaxCandidates) best integer vectors for (L, d, z_hat) of size k (the
/// blocks the caller passes: the whole decorrelated problem or its trailing k x k block, which is
/// the exact LtDL of that subset's marginal covariance). Writes candidates (k x m, columns sorted
/// by ascending distance) and sqnorm (m). Allocates nothing.
SearchOutcome search_integer_candidates(const Eigen::Ref<const Eigen::MatrixXd>& L, const Eigen::Ref<const Eigen::VectorXd>& d,
                                        const Eigen::Ref<const Eigen::VectorXd>& z_hat, Eigen::Index m, long max_steps,
                                        SearchWorkspace& workspace, CandidateMatrix& candidates, CandidateVector& sqnorm);

}  // namespace visors::nav
