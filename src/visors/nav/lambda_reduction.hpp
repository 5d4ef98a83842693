#pragma once
// Decorrelation of a float ambiguity covariance for integer least squares: the LAMBDA reduction
// (Teunissen 1995, J. Geodesy 70:65-82; de Jonge & Tiberius 1996, LGR series 12) preceded by the
// symmetric pivoting of MLAMBDA's reduction (Chang, Yang & Zhou 2005, J. Geodesy 79:552-565,
// sec. 3.1).
//
// Factorisation from the last index backwards, Q = L' diag(d) L with L unit lower triangular:
// d(n-1) is the variance of the last ambiguity, d(i) the variance of ambiguity i conditioned on
// i+1..n-1 (docs/algorithms/ambiguity-resolution.md#ltdl-factorisation). The pivoting puts, at
// every step, the ambiguity with the smallest conditional variance last, so the search (which
// starts at the last index) starts from the best determined ones. The reduction then applies
// integer Gauss transformations (|L(i,j)| <= 1/2 for i > j) and permutations of neighbours j, j+1
// while that lowers d(j+1) (d(j) + L(j+1,j)^2 d(j+1) < d(j+1)), so the d's end as close to
// ascending from the back as the lattice allows. Every operation is unimodular: Z (integer, det
// +-1) gives z = Z' a, Q_z = Z' Q Z = L' diag(d) L, and maps back exactly, a = Z^-T z, with no
// linear solve. Z is kept as its sequence of elementary operations (unimodular_transform.hpp).
//
// Bounded work: the number of permutations is capped (max_permutations); reaching the cap leaves
// a valid, only less decorrelated Z (the search stays exact, it may take more steps) and is
// reported (permutation_limit_reached).

#include <Eigen/Core>

#include "visors/nav/ambiguity_capacity.hpp"
#include "visors/nav/unimodular_transform.hpp"

namespace visors::nav {

struct Decorrelation {
  Eigen::Index n = 0;
  AmbiguityMatrix L;      // unit lower triangular, Q_z = L' diag(d) L (only i >= j meaningful)
  AmbiguityVector d;      // conditional variances of z [cycles^2]
  UnimodularTransform transform;  // Z: z = Z' a
  long permutations = 0;  // neighbour permutations done by the reduction
  bool permutation_limit_reached = false;
};

/// Workspace of decorrelate (the Schur complements of the pivoted factorisation).
struct DecorrelationWorkspace {
  AmbiguityMatrix schur;
};

/// Pivoted LtDL of the symmetric Q (n x n, n <= kMaxAmbiguities; the caller validated size,
/// finiteness and symmetry) followed by the LAMBDA reduction with at most max_permutations
/// neighbour permutations. Returns false, leaving `out` unspecified, when a pivot is not positive
/// (Q not positive definite to working precision). Allocates nothing.
bool decorrelate(const Eigen::Ref<const Eigen::MatrixXd>& Q, long max_permutations, Decorrelation& out,
                 DecorrelationWorkspace& workspace);

/// Unpivoted LtDL of Q from the last index backwards (the classic LAMBDA factorisation): false
/// when a pivot is not positive. For comparison with the pivoted factorisation and for tests.
bool factor_ltdl(const Eigen::Ref<const Eigen::MatrixXd>& Q, AmbiguityMatrix& L, AmbiguityVector& d,
                 DecorrelationWorkspace& workspace);

}  // namespace visors::nav
