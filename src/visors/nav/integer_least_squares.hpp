#pragma once
// Integer least-squares ambiguity resolution (LAMBDA with the MLAMBDA search): from float
// ambiguities a [cycles] and their covariance Q [cycles^2] to the m best integer vectors
//   z_1..z_m minimising (a - z)' Q^-1 (a - z),
// their squared norms, the ratio s_2 / s_1, the bootstrapped success rate of the decorrelated
// problem and, for partial fixing, the largest subset of decorrelated combinations whose
// success rate reaches a required level (docs/algorithms/ambiguity-resolution.md).
//
// Steps, each in its own file: validation (here), removal of the integer parts of a (values near
// 1e9 cycles stay exact), decorrelate (lambda_reduction.hpp), search_integer_candidates
// (mlambda_search.hpp), back-transform a = Z^-T z exactly by the reduction's integer operations.
//
// Fixed capacity (kMaxAmbiguities, kMaxCandidates); all storage is made by create(), resolve()
// allocates nothing and returns a status (no Error strings in the step). A capped search returns
// kSearchLimit and no candidate: never a silent wrong answer.

#include <memory>
#include <string_view>

#include <Eigen/Core>

#include "visors/core/status.hpp"
#include "visors/nav/ambiguity_capacity.hpp"
#include "visors/nav/lambda_reduction.hpp"

namespace visors::nav {

struct IlsSettings {
  int candidates = 2;                   // m best vectors searched, 1..kMaxCandidates (2 for the ratio)
  long max_search_steps = 1'000'000;    // cap on search steps (level visits), >= 1
  long max_permutations = 100'000;      // cap on reduction permutations, >= 0
  double symmetry_tolerance = 1e-9;     // |Q_ij - Q_ji| <= tol * sqrt(Q_ii Q_jj) accepted [-]
};

/// Each value checked; the error names the field.
core::Status validate(const IlsSettings& settings);

enum class IlsStatus {
  kOk,
  kEmpty,                // n = 0
  kTooManyAmbiguities,   // n > kMaxAmbiguities
  kSizeMismatch,         // a and Q disagree, or Q not square
  kNotFinite,            // NaN or infinity in a or Q
  kNotSymmetric,         // beyond symmetry_tolerance
  kNotPositiveDefinite,  // a non-positive pivot in the factorisation
  kSearchLimit,          // max_search_steps reached: no candidate is returned
};

/// "ok", "empty", "too_many_ambiguities", "size_mismatch", "not_finite", "not_symmetric",
/// "not_positive_definite", "search_limit".
std::string_view to_string(IlsStatus status);

/// The decorrelated problem of the last decorrelate(): z_hat = Z' a and Q_z = L' diag(d) L.
struct DecorrelatedAmbiguities {
  const Decorrelation& decorrelation;
  const AmbiguityVector& z_hat;  // [cycles], integer parts included
};

/// Result of a search over the trailing k of the n decorrelated ambiguities (k = n: full fix).
struct IlsSolution {
  Eigen::Index n = 0;          // ambiguities
  Eigen::Index fixed = 0;      // k: decorrelated combinations searched (the trailing k)
  Eigen::Index found = 0;      // candidates found (m)
  CandidateMatrix z;           // k x m: integer values of the combinations Z(:, n-k..)' a, best first
  CandidateMatrix a;           // n x m: the candidates in the original space (only when k = n)
  CandidateVector sqnorm;      // m: squared norms in the metric of the searched (marginal) covariance
  double ratio = 0.0;          // sqnorm(1) / sqnorm(0) (+inf when sqnorm(0) = 0); 0 when m = 1
  double success_rate = 0.0;   // bootstrapped success rate of the k combinations searched
  long search_steps = 0;
};

class IntegerLeastSquares {
 public:
  static core::Result<IntegerLeastSquares> create(const IlsSettings& settings = {});

  /// Validates (a, Q), removes the integer parts of a, decorrelates Q. kOk or the input's problem.
  IlsStatus decorrelate(const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& Q);
  /// After a successful decorrelate(): the decorrelated problem.
  [[nodiscard]] DecorrelatedAmbiguities decorrelated() const;
  /// After a successful decorrelate(): Z (n x n, integer, z = Z' a), formed from the reduction's
  /// operations on the first call and kept until the next decorrelate(). Allocates nothing.
  [[nodiscard]] const AmbiguityMatrix& transformation() const;
  /// Bootstrapped success rate of all n decorrelated ambiguities (after decorrelate()).
  [[nodiscard]] double success_rate_bootstrap() const;
  /// Largest k whose trailing decorrelated combinations reach min_success_rate (0..n).
  [[nodiscard]] Eigen::Index partial_fix_size(double min_success_rate) const;

  /// Searches the settings' m best integer vectors of the trailing k combinations (1 <= k <= n);
  /// k = n also back-transforms them to the original space. kOk or kSearchLimit.
  IlsStatus search(Eigen::Index k);
  /// decorrelate() then search(n).
  IlsStatus resolve(const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& Q);

  [[nodiscard]] const IlsSolution& solution() const;
  [[nodiscard]] const IlsSettings& settings() const { return settings_; }

  IntegerLeastSquares(IntegerLeastSquares&&) noexcept;
  IntegerLeastSquares& operator=(IntegerLeastSquares&&) noexcept;
  ~IntegerLeastSquares();

 private:
  struct Workspace;
  IntegerLeastSquares(const IlsSettings& settings, std::unique_ptr<Workspace> workspace);
  IlsStatus validate_input(const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& Q) const;
  void back_transform();

  IlsSettings settings_;
  std::unique_ptr<Workspace> w_;
};

}  // namespace visors::nav
