#include "visors/nav/bootstrap.hpp"

#include <cmath>

#include "visors/nav/nearest_integer.hpp"

namespace visors::nav {

double rounding_success_rate(double d_i) { return std::erf(1.0 / std::sqrt(8.0 * d_i)); }

double bootstrap_success_rate(const Eigen::Ref<const Eigen::VectorXd>& d) {
  double p = 1.0;
  for (Eigen::Index i = 0; i < d.size(); ++i) p *= rounding_success_rate(d(i));
  return p;
}

Eigen::Index partial_fix_size(const Eigen::Ref<const Eigen::VectorXd>& d, double min_success_rate) {
  const Eigen::Index n = d.size();
  double p = 1.0;
  Eigen::Index k = 0;
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    p *= rounding_success_rate(d(i));
    if (p < min_success_rate) break;
    k = n - i;
  }
  return k;
}

void bootstrap_integers(const Eigen::Ref<const Eigen::MatrixXd>& L, const Eigen::Ref<const Eigen::VectorXd>& z_hat,
                        AmbiguityVector& z) {
  const Eigen::Index n = z_hat.size();
  z.resize(n);
  AmbiguityVector residual(n);  // z_j - z_hat_{j|J} of the levels already rounded
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    double estimate = z_hat(i);
    for (Eigen::Index j = i + 1; j < n; ++j) estimate += residual(j) * L(j, i);
    z(i) = nearest_integer(estimate);
    residual(i) = z(i) - estimate;
  }
}

}  // namespace visors::nav
