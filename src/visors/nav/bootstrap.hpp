#pragma once
// Integer bootstrapping (sequential conditional rounding) and its success rate (Teunissen 1998,
// "Success probability of integer GPS ambiguity rounding and bootstrapping", J. Geodesy 72:606-612;
// docs/algorithms/ambiguity-resolution.md#bootstrapped-success-rate):
//   P_s,IB = prod_i (2 Phi(1 / (2 sqrt(d_i))) - 1) = prod_i erf(1 / sqrt(8 d_i)),
// with d the conditional variances of the factorisation in the order the estimator rounds (from
// the last index). Exact for the bootstrapped estimator; a lower bound of the integer least-squares
// success rate (Teunissen 1999, J. Geodesy 73:587-593), sharpest after decorrelation.

#include <Eigen/Core>

#include "visors/nav/ambiguity_capacity.hpp"

namespace visors::nav {

/// Success rate of one component rounded with conditional variance d_i [cycles^2].
double rounding_success_rate(double d_i);

/// P_s,IB of the whole vector whose conditional variances are d.
double bootstrap_success_rate(const Eigen::Ref<const Eigen::VectorXd>& d);

/// Partial ambiguity resolution (docs/algorithms/ambiguity-resolution.md#partial-fixing; Teunissen,
/// Joosten & Tiberius 1999, ION NTM 1999): the largest k such that the trailing k components (the
/// best determined ones after the reduction) have prod_{i >= n-k} rounding_success_rate(d_i) >=
/// min_success_rate. 0 when even the last component alone falls short.
Eigen::Index partial_fix_size(const Eigen::Ref<const Eigen::VectorXd>& d, double min_success_rate);

/// The bootstrapped integer vector: z_i = round(z_hat_{i|I}) from the last index down, each
/// conditioned on the integers already chosen. Allocation-free with n <= kMaxAmbiguities.
void bootstrap_integers(const Eigen::Ref<const Eigen::MatrixXd>& L, const Eigen::Ref<const Eigen::VectorXd>& z_hat,
                        AmbiguityVector& z);

}  // namespace visors::nav
