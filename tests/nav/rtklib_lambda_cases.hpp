#pragma once
// RTKLIB's published LAMBDA unit-test cases, test/utest/t_lambda.c (tomojitakasu/RTKLIB;
// docs/algorithms/ambiguity-resolution.md#rtklib-utest1-and-utest2): the float ambiguities and
// covariances of utest1 (n = 6) and utest2 (n = 10). Their expected integers and squared norms are
// written beside the assertions that use them.

#include <Eigen/Core>

namespace visors::nav::rtklib {

inline Eigen::MatrixXd utest1_q() {
  Eigen::MatrixXd Q = Eigen::MatrixXd::Constant(6, 6, 0.112202);
  Q.diagonal().setConstant(0.227134);
  Q(5, 5) = 0.434339;
  for (int i = 0; i < 5; ++i) Q(i, 5) = Q(5, i) = 0.103473;
  return Q;
}

inline Eigen::VectorXd utest1_a() {
  Eigen::VectorXd a(6);
  a << 1585184.171, -6716599.430, 3915742.905, 7627233.455, 9565990.879, 989457273.200;
  return a;
}

// Q = [[A, B], [B, C]], 5 x 5 blocks with one diagonal and one off-diagonal value.
inline Eigen::MatrixXd utest2_q() {
  auto block = [](double diagonal, double off) {
    Eigen::MatrixXd b = Eigen::MatrixXd::Constant(5, 5, off);
    b.diagonal().setConstant(diagonal);
    return b;
  };
  Eigen::MatrixXd Q(10, 10);
  Q << block(0.446320, 0.223160), block(0.572775, 0.286388), block(0.572775, 0.286388), block(0.735063, 0.367531);
  return Q;
}

inline Eigen::VectorXd utest2_a() {
  Eigen::VectorXd a(10);
  a << -13324172.755747, -10668894.713608, -7157225.010770, -6149367.974367, -7454133.571066, -5969200.494550,
      8336734.058423, 6186974.084502, -17549093.883655, -13970158.922370;
  return a;
}

}  // namespace visors::nav::rtklib
