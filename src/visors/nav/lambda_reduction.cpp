#include "visors/nav/lambda_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "visors/nav/nearest_integer.hpp"

namespace visors::nav {
namespace {

using Eigen::Index;

// Eliminates index i from the Schur complement `schur` (its leading (i+1) x (i+1) block): row i of
// L and d(i), then the rank-one downdate of the leading i x i block. False for a non-positive pivot.
bool eliminate(Index i, AmbiguityMatrix& schur, AmbiguityMatrix& L, AmbiguityVector& d) {
  const double pivot = schur(i, i);
  if (!(pivot > 0.0) || !std::isfinite(pivot)) return false;
  d(i) = pivot;
  L(i, i) = 1.0;
  L.row(i).head(i) = schur.row(i).head(i) / pivot;
  // Q = L' D L: removing i leaves A(j,k) - A(j,i) A(i,k) / A(i,i) = A(j,k) - d(i) L(i,j) L(i,k).
  for (Index k = 0; k < i; ++k) {
    schur.col(k).head(i).noalias() -= (pivot * L(i, k)) * L.row(i).head(i).transpose();
  }
  return true;
}

// Symmetric pivoting: the index of the smallest remaining diagonal goes to position i, so it is
// eliminated now and ends last among 0..i (MLAMBDA, Chang et al. 2005, sec. 3.1). Rows i+1.. of L
// are already final; their columns p and i are exchanged with the ambiguities.
void pivot_smallest_last(Index i, Decorrelation& out, AmbiguityMatrix& schur) {
  Index p = 0;
  schur.diagonal().head(i + 1).minCoeff(&p);
  if (p == i) return;
  schur.row(p).head(i + 1).swap(schur.row(i).head(i + 1));
  schur.col(p).head(i + 1).swap(schur.col(i).head(i + 1));
  const Index n = out.n;
  for (Index k = i + 1; k < n; ++k) std::swap(out.L(k, p), out.L(k, i));
  out.transform.exchange(p, i);
}

// Column operations of L on raw columns: Eigen's evaluation of these short dynamic-size
// segments cost several times the arithmetic (callgrind, 2026-11).
void axpy(Index count, double a, const double* __restrict x, double* __restrict y) {
  for (Index r = 0; r < count; ++r) y[r] += a * x[r];
}
void swap_columns(Index count, double* __restrict x, double* __restrict y) {
  for (Index r = 0; r < count; ++r) std::swap(x[r], y[r]);
}
double* column(AmbiguityMatrix& m, Index j) { return m.data() + j * m.outerStride(); }

// Integer Gauss transformation making |L(i,j)| <= 1/2 (i > j): column j of L and Z minus
// mu = round(L(i,j)) times column i.
void gauss_transform(Index i, Index j, Decorrelation& out) {
  const double mu = nearest_integer(out.L(i, j));
  if (mu == 0.0) return;
  axpy(out.n - i, -mu, column(out.L, i) + i, column(out.L, j) + i);
  out.transform.subtract(i, j, mu);
}

// Permutation of neighbours j and j+1 with the new conditional variance delta of j+1 (de Jonge &
// Tiberius 1996, eq. 3.19-3.21; docs/algorithms/ambiguity-resolution.md#lambda-reduction).
void permute(Index j, double delta, Decorrelation& out) {
  const Index n = out.n;
  AmbiguityMatrix& L = out.L;
  const double l = L(j + 1, j);
  const double eta = out.d(j) / delta;
  const double lambda = out.d(j + 1) * l / delta;
  out.d(j) = eta * out.d(j + 1);
  out.d(j + 1) = delta;
  for (Index k = 0; k < j; ++k) {
    const double a0 = L(j, k);
    const double a1 = L(j + 1, k);
    L(j, k) = -l * a0 + a1;
    L(j + 1, k) = eta * a0 + lambda * a1;
  }
  L(j + 1, j) = lambda;
  swap_columns(n - j - 2, column(L, j) + j + 2, column(L, j + 1) + j + 2);
  out.transform.exchange(j, j + 1);
}

// Rows of each column of L that may exceed 1/2 since the column was last size-reduced: rows
// below first_dirty(j) are reduced, so their Gauss transformations would be no-ops and are
// skipped. A permutation at p rewrites rows p, p+1 of the columns left of p, all of column p, and
// moves column p's rows below p+1 into column p+1 (permute above); nothing else changes L.
struct DirtyRows {
  Eigen::Matrix<Index, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxAmbiguities, 1> first_dirty;

  explicit DirtyRows(Index n) : first_dirty(n) {
    for (Index j = 0; j < n; ++j) first_dirty(j) = j + 1;
  }
  void permuted(Index p) {
    first_dirty(p + 1) = std::max(first_dirty(p), p + 2);
    first_dirty(p) = p + 1;
    for (Index k = 0; k < p; ++k) first_dirty(k) = std::min(first_dirty(k), p);
  }
  void reduced(Index j, Index n) { first_dirty(j) = n; }
};

// LAMBDA reduction with lazy Gauss transformations (de Jonge & Tiberius 1996;
// docs/algorithms/ambiguity-resolution.md#lambda-reduction): column j is (re)reduced only when a
// permutation at or below j may have changed it, and the walk restarts after each permutation at p
// from p+1 (the first pair whose decision it can change; the original restarts from n-2 and finds
// nothing to do above p+1). Only the rows a permutation may have spoilt are re-reduced (DirtyRows),
// which leaves exactly the same sequence of non-trivial transformations as the full re-reduction
// and a quarter of its cost (2026-11). The variant of MLAMBDA (only the subdiagonal reduced before
// each decision, one size reduction at the end) was tried: 40 % fewer instructions, but L grows
// between size reductions and L' D L lost up to 3e-8 of Z' Q Z on condition-1e6 problems
// (tests/nav, 2026-11); this order keeps it at round-off. The relative margin keeps rounding from
// permuting a pair back and forth.
void reduce(long max_permutations, Decorrelation& out) {
  constexpr double kMargin = 1e-12;
  const Index n = out.n;
  DirtyRows dirty(n);
  Index j = n - 2;
  Index last_permutation = n - 2;
  while (j >= 0) {
    if (j <= last_permutation) {
      for (Index i = std::max(j + 1, dirty.first_dirty(j)); i < n; ++i) gauss_transform(i, j, out);
      dirty.reduced(j, n);
    }
    const double delta = out.d(j) + out.L(j + 1, j) * out.L(j + 1, j) * out.d(j + 1);
    if (delta < out.d(j + 1) * (1.0 - kMargin)) {
      if (out.permutations >= max_permutations) {
        out.permutation_limit_reached = true;
        return;
      }
      permute(j, delta, out);
      dirty.permuted(j);
      ++out.permutations;
      last_permutation = j;
      j = std::min(j + 1, n - 2);
    } else {
      --j;
    }
  }
}

void start(Index n, const Eigen::Ref<const Eigen::MatrixXd>& Q, AmbiguityMatrix& schur) {
  schur.resize(n, n);
  // Symmetric by construction from the lower triangle (the caller checked symmetry).
  schur.triangularView<Eigen::Lower>() = Q.triangularView<Eigen::Lower>();
  schur.triangularView<Eigen::StrictlyUpper>() = Q.transpose().triangularView<Eigen::StrictlyUpper>();
}

}  // namespace

bool factor_ltdl(const Eigen::Ref<const Eigen::MatrixXd>& Q, AmbiguityMatrix& L, AmbiguityVector& d,
                 DecorrelationWorkspace& workspace) {
  const Index n = Q.rows();
  start(n, Q, workspace.schur);
  L.setZero(n, n);
  d.resize(n);
  for (Index i = n - 1; i >= 0; --i) {
    if (!eliminate(i, workspace.schur, L, d)) return false;
  }
  return true;
}

bool decorrelate(const Eigen::Ref<const Eigen::MatrixXd>& Q, long max_permutations, Decorrelation& out,
                 DecorrelationWorkspace& workspace) {
  const Index n = Q.rows();
  out.n = n;
  out.permutations = 0;
  out.permutation_limit_reached = false;
  out.transform.reset(n);
  start(n, Q, workspace.schur);
  out.L.setZero(n, n);
  out.d.resize(n);
  for (Index i = n - 1; i >= 0; --i) {
    pivot_smallest_last(i, out, workspace.schur);
    if (!eliminate(i, workspace.schur, out.L, out.d)) return false;
  }
  reduce(max_permutations, out);
  return true;
}

}  // namespace visors::nav
