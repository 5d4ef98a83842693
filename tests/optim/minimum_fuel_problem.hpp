#pragma once
// The planner's minimum-fuel problem in conic form, with random data, shared by the optim tests
// and the conic benchmark: min sum_k t_k s.t. sum_k B_k dv_k = b (6 rows), ||dv_k|| <= t_k.
// Variables [dv_1 .. dv_N (3 each), t_1 .. t_N]; cone k is (t_k, dv_k), so G_k = -I on its own
// columns and h = 0. B and b are standard normal (18 N + 6 draws: an even count, so a fresh
// std::normal_distribution per call leaves the generator where a shared one would).

#include <random>

#include <Eigen/Core>

#include "visors/optim/conic_problem.hpp"

namespace visors::optim::test {

inline ConicDimensions minimum_fuel_dimensions(int impulses) {
  ConicDimensions dims;
  dims.n = 4 * impulses;
  dims.p = 6;
  dims.q.assign(static_cast<std::size_t>(impulses), 4);
  return dims;
}

inline ConicProblem minimum_fuel_problem(int impulses, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  const int n = 4 * impulses;
  ConicProblem pr;
  pr.c = Eigen::VectorXd::Zero(n);
  pr.c.tail(impulses).setOnes();
  pr.G = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < impulses; ++k) {
    pr.G(4 * k, 3 * impulses + k) = -1.0;
    for (int i = 0; i < 3; ++i) pr.G(4 * k + 1 + i, 3 * k + i) = -1.0;
  }
  pr.h = Eigen::VectorXd::Zero(n);
  pr.A = Eigen::MatrixXd::Zero(6, n);
  for (int r = 0; r < 6; ++r) {
    for (int j = 0; j < 3 * impulses; ++j) pr.A(r, j) = normal(rng);
  }
  pr.b = Eigen::VectorXd::NullaryExpr(6, [&] { return normal(rng); });
  return pr;
}

}  // namespace visors::optim::test
