#pragma once
// Feeding an integer fix back into the float states
// (docs/algorithms/ambiguity-resolution.md#fixed-solution-update): the update of
// ALL states x (n_x) with covariance P given k fixed integer combinations C x = z,
//   S = C P C' + s I,  K = P C' S^-1,  x+ = x + K (z - C x),  P+ = P - K C P,
// - s = 0: the exact conditioning of the Gaussian (x, P) on C x = z, the fixed solution (RTKLIB
//   resamb_LAMBDA, "continuous" AR output: x+ goes to guidance, the float filter
//   keeps running on its own copy);
// - s > 0: a Kalman update with the pseudo-measurement z = C x + v, v ~ N(0, s I) [cycles^2], the
//   fix-and-hold constraint (RTKLIB holdamb, VAR_HOLDAMB = 0.001 cycles^2).
//
// Computed with the Cholesky factor S = L L': W = L^-1 (P C')' (k x n_x), v = L^-1 (z - C x),
//   x+ = x + W' v,  P+ = P - W' W,
// since K = P C' L^-T L^-1. P - W' W is the symmetric form of P - K C P (one triangular solve, the
// subtracted term symmetric positive semidefinite by construction), computed on the lower triangle
// and mirrored: P+ is exactly symmetric. Only the columns of C with a non-zero entry enter C P and
// C x (a fix touches the ambiguity states only: 24 of the filter's 98). This is the "simple" form
// of the conditional update, not the Joseph form: with s = 0 the Joseph form (I - K C) P (I - K C)'
// equals it only when K is the optimal gain, and it costs two n_x^3 products per update; the
// symmetric downdate keeps P+ symmetric, and its positive semidefiniteness is tested
// (tests/nav/test_fixed_solution.cpp).
//
// Numerically positive definite S: Eigen's LLT succeeds and every squared pivot L_jj^2 exceeds
// kRelativePivot max_j S_jj. Below that, the solve would lose most digits (redundant fixed
// combinations with s = 0, or a P that is not positive definite); the update is refused and
// x, P are untouched. NaN or infinity in any input is refused the same way. No NaN ever reaches
// x or P.
//
// Fixed capacity: n_x <= max_states, k <= max_constraints (<= kMaxAmbiguities), chosen at
// create(); apply() and fixed_constraints() allocate nothing.

#include <string_view>
#include <utility>

#include <Eigen/Core>

#include "visors/core/result.hpp"
#include "visors/nav/ambiguity_acceptance.hpp"
#include "visors/nav/ambiguity_capacity.hpp"
#include "visors/nav/double_difference.hpp"
#include "visors/nav/integer_least_squares.hpp"

namespace visors::nav {

class FixedSolutionUpdate {
 public:
  /// Capacity: max_states >= 1 filter states, 1 <= max_constraints <= kMaxAmbiguities fixed
  /// combinations. The error names the field.
  static core::Result<FixedSolutionUpdate> create(Eigen::Index max_states, Eigen::Index max_constraints = kMaxAmbiguities);

  enum class Status {
    kOk,
    kSizeMismatch,         // x, P, C, z disagree (P n_x x n_x, C k x n_x, z k)
    kOutOfCapacity,        // n_x > max_states or k > max_constraints
    kNotFinite,            // NaN or infinity in x, P, C, z or the variance
    kNegativeVariance,     // variance < 0
    kNotPositiveDefinite,  // C P C' + s I not numerically positive definite
  };

  /// In place on (x, P): conditions on C x = z (variance = 0) or applies the hold
  /// pseudo-measurement of variance [cycles^2] (> 0). k = 0 is a no-op returning kOk. On any
  /// status but kOk, x and P are untouched. Allocates nothing.
  Status apply(Eigen::Ref<Eigen::VectorXd> x, Eigen::Ref<Eigen::MatrixXd> P, const Eigen::Ref<const Eigen::MatrixXd>& C,
               const Eigen::Ref<const Eigen::VectorXd>& z, double variance = 0.0);

  /// The same with consider states: gain_mask (n_x, entries 0 or 1) zeroes the gain of each state
  /// whose entry is 0, so its estimate is held, and P+ is the Joseph form for that gain,
  ///   P+ = (I - K C) P (I - K C)' + s K K' = P - K G' - G K' + K S K',  G = P C',
  /// which holds for any K (an all-ones mask gives the update above). O(n_x^2 k). Allocates nothing.
  Status apply(Eigen::Ref<Eigen::VectorXd> x, Eigen::Ref<Eigen::MatrixXd> P, const Eigen::Ref<const Eigen::MatrixXd>& C,
               const Eigen::Ref<const Eigen::VectorXd>& z, double variance, const Eigen::Ref<const Eigen::VectorXd>& gain_mask);

  [[nodiscard]] Eigen::Index max_states() const { return max_states_; }
  [[nodiscard]] Eigen::Index max_constraints() const { return max_constraints_; }

 private:
  FixedSolutionUpdate(Eigen::Index max_states, Eigen::Index max_constraints);
  Status check(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::MatrixXd>& P,
               const Eigen::Ref<const Eigen::MatrixXd>& C, const Eigen::Ref<const Eigen::VectorXd>& z,
               double variance) const;
  bool factor(Eigen::Index k);
  Status innovation_system(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::MatrixXd>& P,
                           const Eigen::Ref<const Eigen::MatrixXd>& C, const Eigen::Ref<const Eigen::VectorXd>& z,
                           double variance);
  static std::pair<Eigen::Index, Eigen::Index> column_span(const Eigen::Ref<const Eigen::MatrixXd>& C);

  Eigen::Index max_states_ = 0;
  Eigen::Index max_constraints_ = 0;
  Eigen::MatrixXd S_;  // max_constraints x max_constraints: C P C' + s I, then its Cholesky factor
  Eigen::MatrixXd W_;  // max_constraints x max_states: C P, then L^-1 C P
  Eigen::VectorXd v_;  // max_constraints: z - C x, then L^-1 (z - C x)
  Eigen::MatrixXd G_;  // max_states x max_constraints: P C' (the consider form)
  Eigen::MatrixXd K_;  // max_states x max_constraints: the masked gain, then K S
};

/// "ok", "size_mismatch", "out_of_capacity", "not_finite", "negative_variance",
/// "not_positive_definite".
std::string_view to_string(FixedSolutionUpdate::Status status);

/// The fixed constraints of an accepted integer solution: C = Z(:, n-k..n-1)' G (k x n_x) and
/// z = the best candidate ils.solution().z.col(0) (k integers, integer parts included: the ILS
/// adds Z' round(a) back, so C x_float = Z_k' a_float is near z), for the k combinations fixed
/// (k = n full fix, k < n partial fix). `fix` must be the outcome of the last resolve_ambiguities
/// with `ils` on dd's a and Q: it guards against a stale solution (a float outcome leaves the
/// previous epoch's integers in ils). Writes the top k rows of C (C.cols() == n_x, C.rows() >= k)
/// and the head of z (z.size() >= k). Returns k; 0 (nothing written) when the fix is a float, or
/// the sizes of fix, ils, dd, C, z disagree. Allocates nothing.
Eigen::Index fixed_constraints(const AmbiguityFix& fix, const IntegerLeastSquares& ils, const DoubleDifferenceAmbiguities& dd,
                               Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> z);

}  // namespace visors::nav
