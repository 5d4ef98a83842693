#include "nav/mlambda_search.hpp"

#include <cmath>
#include <limits>

#include "nav/nearest_integer.hpp"

namespace visors::nav {
namespace {

using Eigen::Index;

double sign_toward(double y) { return y <= 0.0 ? -1.0 : 1.0; }

// The m best distances found so far: candidate storage with the index of the worst.
struct Best {
  CandidateMatrix& z;
  CandidateVector& s;
  Index m = 0;
  Index count = 0;
  Index worst = 0;

  [[nodiscard]] double bound() const { return count < m ? std::numeric_limits<double>::infinity() : s(worst); }

  void offer(const AmbiguityVector& level_z, Index k, double distance) {
    Index slot = count;
    if (count < m) {
      ++count;
    } else {
      slot = worst;
    }
    z.col(slot) = level_z.head(k);
    s(slot) = distance;
    s.head(count).maxCoeff(&worst);
  }

  // Insertion sort by distance (m is small), ascending.
  void sort() {
    for (Index i = 1; i < count; ++i) {
      for (Index j = i; j > 0 && s(j) < s(j - 1); --j) {
        std::swap(s(j), s(j - 1));
        z.col(j).swap(z.col(j - 1));
      }
    }
  }
};

// Moves level k's integer to its next zig-zag value around the conditional estimate.
void next_integer(Index k, SearchWorkspace& w) {
  w.z(k) += w.step(k);
  w.step(k) = -w.step(k) - sign_toward(w.step(k));
}

// Enters level k (below k+1): its partial distance, its conditional estimate from the integers
// chosen above, the nearest integer and the first zig-zag direction. The conditional sums run on
// raw columns: this is the search's inner loop, executed once per step (Eigen's expression setup
// on these short dynamic columns cost ten times the arithmetic, callgrind 2026-11).
void descend(Index k, double distance, const Eigen::Ref<const Eigen::VectorXd>& z_hat, SearchWorkspace& w) {
  w.distance(k) = distance;
  const double residual = w.z(k + 1) - w.estimate(k + 1);
  double* sums = &w.sums_t.coeffRef(0, k);
  const double* sums_above = &w.sums_t.coeffRef(0, k + 1);
  const double* l_row = &w.L_t.coeffRef(0, k + 1);
  for (Index i = 0; i <= k; ++i) sums[i] = sums_above[i] + residual * l_row[i];
  w.estimate(k) = z_hat(k) + sums[k];
  w.z(k) = nearest_integer(w.estimate(k));
  w.step(k) = sign_toward(w.estimate(k) - w.z(k));
}

}  // namespace

SearchOutcome search_integer_candidates(const Eigen::Ref<const Eigen::MatrixXd>& L, const Eigen::Ref<const Eigen::VectorXd>& d,
                                        const Eigen::Ref<const Eigen::VectorXd>& z_hat, Index m, long max_steps,
                                        SearchWorkspace& w, CandidateMatrix& candidates, CandidateVector& sqnorm) {
  const Index n = d.size();
  w.L_t = L.transpose();
  w.sums_t.setZero(n, n);
  w.distance.resize(n);
  w.estimate.resize(n);
  w.z.resize(n);
  w.step.resize(n);
  candidates.resize(n, m);
  sqnorm.resize(m);
  Best best{candidates, sqnorm, m};

  SearchOutcome outcome;
  Index k = n - 1;
  w.distance(k) = 0.0;
  w.estimate(k) = z_hat(k);
  w.z(k) = nearest_integer(w.estimate(k));
  w.step(k) = sign_toward(w.estimate(k) - w.z(k));
  for (;;) {
    if (outcome.steps >= max_steps) {
      outcome.status = SearchStatus::kStepLimit;
      break;
    }
    ++outcome.steps;
    const double y = w.estimate(k) - w.z(k);
    const double distance = w.distance(k) + y * y / d(k);
    if (distance < best.bound()) {
      if (k > 0) {
        --k;
        descend(k, distance, z_hat, w);
      } else {
        best.offer(w.z, n, distance);
        next_integer(0, w);
      }
    } else {
      if (k == n - 1) break;  // every branch is closed: the stored vectors are the m best
      ++k;
      next_integer(k, w);
    }
  }
  best.sort();
  outcome.found = best.count;
  return outcome;
}

}  // namespace visors::nav
