#pragma once
// The two families of integer least-squares problems of the IAR benchmark, 50 seeded
// instances per size n, shared by bench_ambiguity.cpp and the exporter that hands the very same
// problems to peer implementations (bench/peers, scripts/bench_rtklib_lambda.sh):
// (1) single-epoch dual-frequency short-baseline DD geometry (tests/support/dd_geometry.hpp):
//     n/2 + 1 satellites, azimuth uniform, sin(elevation) uniform in [sin 10 deg, 1], highest as
//     reference, baseline + n ambiguities (L1, L2), 3 mm phase and 0.3 m code undifferenced, DD
//     cofactor 2(I + 11'); integers uniform in +-1e6 plus noise from Q;
// (2) random SPD Q = U diag(ev) U', U Haar orthogonal, ev log-spaced in [1e-6, 1] cycles^2
//     (condition 1e6), float ambiguities uniform in +-1e6.

#include <Eigen/Cholesky>
#include <cmath>
#include <random>
#include <vector>

#include "support/dd_geometry.hpp"
#include "support/random_orthogonal.hpp"

namespace visors::bench {

struct IlsInstance {
  Eigen::VectorXd a;  // float ambiguities [cycles]
  Eigen::MatrixXd Q;  // their covariance [cycles^2]
};

inline std::vector<IlsInstance> dd_family(int n) {
  std::vector<IlsInstance> out;
  std::mt19937_64 rng(1400 + n);
  test::DdGeometryOptions o;
  o.satellites = n / 2 + 1;
  o.frequencies = 2;
  for (int k = 0; k < 50; ++k) {
    IlsInstance inst;
    inst.Q = test::dd_ambiguity_covariance(o, rng);
    const Eigen::MatrixXd chol = inst.Q.llt().matrixL();
    inst.a = test::float_ambiguities(test::random_integers(n, 1e6, rng), chol, rng);
    out.push_back(inst);
  }
  return out;
}

inline std::vector<IlsInstance> random_spd_family(int n) {
  std::vector<IlsInstance> out;
  std::mt19937_64 rng(2400 + n);
  std::uniform_real_distribution<double> offset(-1e6, 1e6);
  Eigen::VectorXd ev(n);
  for (int i = 0; i < n; ++i) ev(i) = std::pow(10.0, -6.0 + 6.0 * i / (n - 1));  // log-spaced [1e-6, 1]
  for (int k = 0; k < 50; ++k) {
    IlsInstance inst;
    inst.Q = test::spd_with_eigenvalues(test::haar_orthogonal(n, rng), ev);
    inst.a.resize(n);
    for (int i = 0; i < n; ++i) inst.a(i) = offset(rng);
    out.push_back(inst);
  }
  return out;
}

}  // namespace visors::bench
