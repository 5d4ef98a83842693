#include "visors/nav/mlambda_search.hpp"

#include <cmath>
#include <limits>

#include "visors/nav/nearest_integer.hpp"

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

  void offer(const double* level_z, Index k, double distance) {
    Index slot = count;
    if (count < m) {
      ++count;
    } else {
      slot = worst;
    }
    z.col(slot) = Eigen::Map<const Eigen::VectorXd>(level_z, k);
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

// The search state as raw arrays of the workspace. This is the inner loop, executed once per
// step: through Eigen's accessors GCC reloaded every data pointer at each step (perf annotate,
// 2026-11), hence local restrict pointers and the reciprocals of d computed once.
//
// Conditional estimates by lazy partial sums (Ghasemmehdi & Agrell 2011, IEEE Trans. Inf. Theory
// 57(6):3530-3536): for each level k the sums P(k, j) = sum over i >= j of e_i L(i,k), with
// e_i = z_i - z_hat_{i|I} the residual of level i, are kept from the last visit, and on entering
// level k only those from the highest level changed since (begin[k]) down to k+1 are redone.
// MLAMBDA's update recomputes the sums of all rows 0..k at every descent (k+1 products; 13 on
// average at n = 24, where the search spends its steps in the middle levels); this one does
// begin[k] - k, in the same order, so the sums are bit-identical.
struct Levels {
  const double* __restrict z_hat;
  const double* __restrict inv_d;     // 1 / d(k) [1/cycles^2]
  const double* __restrict L;         // L, column k holds L(i, k) for i > k
  double* __restrict partial_sums;    // column k holds P(k, j) for j = k+1..n (P(k, n) = 0)
  Index* __restrict begin;            // highest level changed since level k's sums were made
  double* __restrict distance;        // partial distance of the levels above k
  double* __restrict estimate;        // conditional estimate z_hat_{k|K}
  double* __restrict z;               // current integer of each level
  double* __restrict step;            // next zig-zag increment of each level
  Index ld_L;                         // column stride of L
  Index ld_sums;                      // column stride of partial_sums

  // Starts level k at the nearest integer of its conditional estimate, zig-zag toward it.
  void start(Index k) {
    z[k] = nearest_integer(estimate[k]);
    step[k] = sign_toward(estimate[k] - z[k]);
  }

  // Moves level k's integer to its next zig-zag value around the conditional estimate.
  void next_integer(Index k) {
    z[k] += step[k];
    step[k] = -step[k] - sign_toward(step[k]);
  }

  // Enters level k (below k+1) with the partial distance of the levels above. The levels changed
  // since k was last entered are those up to the highest level reached since, which level k+1
  // passes down (begin[k+1]) before it is reset: from now on only k+1 itself changes below it.
  void descend(Index k, double partial_distance) {
    distance[k] = partial_distance;
    if (begin[k + 1] > begin[k]) begin[k] = begin[k + 1];
    begin[k + 1] = k + 1;
    double* sums = partial_sums + k * ld_sums;
    const double* l_col = L + k * ld_L;
    double s = sums[begin[k] + 1];
    for (Index j = begin[k]; j > k; --j) {
      s += (z[j] - estimate[j]) * l_col[j];
      sums[j] = s;
    }
    estimate[k] = z_hat[k] + s;
    start(k);
  }
};

}  // namespace

SearchOutcome search_integer_candidates(const Eigen::Ref<const Eigen::MatrixXd>& L, const Eigen::Ref<const Eigen::VectorXd>& d,
                                        const Eigen::Ref<const Eigen::VectorXd>& z_hat, Index m, long max_steps,
                                        SearchWorkspace& w, CandidateMatrix& candidates, CandidateVector& sqnorm) {
  const Index n = d.size();
  w.L = L;
  w.partial_sums.resize(n + 1, n);
  w.partial_sums.row(n).setZero();  // P(k, n) = 0: no level above the top
  w.begin.resize(n);
  w.begin.setConstant(n - 1);       // nothing computed yet: every level above is new
  w.inv_d = d.cwiseInverse();
  w.z_hat = z_hat;
  w.distance.resize(n);
  w.estimate.resize(n);
  w.z.resize(n);
  w.step.resize(n);
  candidates.resize(n, m);
  sqnorm.resize(m);
  Best best{candidates, sqnorm, m};
  Levels v{w.z_hat.data(),  w.inv_d.data(),    w.L.data(), w.partial_sums.data(), w.begin.data(),
           w.distance.data(), w.estimate.data(), w.z.data(), w.step.data(),         w.L.outerStride(),
           w.partial_sums.outerStride()};

  SearchOutcome outcome;
  Index k = n - 1;
  double bound = best.bound();
  long steps = 0;
  v.distance[k] = 0.0;
  v.estimate[k] = v.z_hat[k];
  v.start(k);
  for (;;) {
    if (steps >= max_steps) {
      outcome.status = SearchStatus::kStepLimit;
      break;
    }
    ++steps;
    const double y = v.estimate[k] - v.z[k];
    const double distance = v.distance[k] + y * y * v.inv_d[k];
    if (distance < bound) {
      if (k > 0) {
        --k;
        v.descend(k, distance);
      } else {
        best.offer(v.z, n, distance);
        bound = best.bound();
        v.next_integer(0);
      }
    } else {
      if (k == n - 1) break;  // every branch is closed: the stored vectors are the m best
      ++k;
      v.next_integer(k);
    }
  }
  outcome.steps = steps;
  best.sort();
  outcome.found = best.count;
  return outcome;
}

}  // namespace visors::nav
