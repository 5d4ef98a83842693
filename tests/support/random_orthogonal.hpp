#pragma once
// Haar-distributed random orthogonal matrices (QR of a Gaussian matrix with the signs of R's
// diagonal moved into Q; Mezzadri 2007, "How to generate random matrices from the classical
// compact groups", Notices AMS 54:592) and the SPD matrices U diag(ev) U' built from them, shared
// by the nav tests and the ambiguity benchmark.

#include <Eigen/Core>
#include <Eigen/QR>
#include <random>

namespace visors::test {

inline Eigen::MatrixXd haar_orthogonal(int n, std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  Eigen::MatrixXd g(n, n);
  for (int i = 0; i < n * n; ++i) g.data()[i] = gauss(rng);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(g);
  Eigen::MatrixXd u = qr.householderQ();
  for (int j = 0; j < n; ++j) u.col(j) *= qr.matrixQR()(j, j) < 0.0 ? -1.0 : 1.0;
  return u;
}

/// U diag(ev) U', symmetrised.
inline Eigen::MatrixXd spd_with_eigenvalues(const Eigen::MatrixXd& u, const Eigen::VectorXd& ev) {
  const Eigen::MatrixXd q = u * ev.asDiagonal() * u.transpose();
  return 0.5 * (q + q.transpose());
}

}  // namespace visors::test
