// A program linked with visors_ambiguity alone (and through it core and Eigen): it builds only if
// the integer ambiguity resolution needs nothing else, and it resolves a small instance. The float
// ambiguities are 0.2 and 0.1 cycles from the integers (1, -1) with 0.1-cycle sigmas and no
// correlation: with a diagonal covariance the integer least-squares solution is the componentwise
// rounding (Teunissen, J. Geodesy 70, 1995, the decorrelated case), i.e. (1, -1), squared norm
// (0.04 + 0.01) / 0.01 = 5, the runner-up (2, -1) at 65: ratio 13. Exit 0 when found, 1 otherwise.
#include <cstdio>
#include <utility>

#include <Eigen/Core>

#include "visors/nav/integer_least_squares.hpp"

int main() {
  auto created = visors::nav::IntegerLeastSquares::create();
  if (!created) {
    std::fprintf(stderr, "create: %s\n", created.error().describe().c_str());
    return 1;
  }
  visors::nav::IntegerLeastSquares ils = std::move(created).value();
  const Eigen::Vector2d a(1.2, -0.9);  // [cycles]
  const Eigen::Matrix2d Q = 0.01 * Eigen::Matrix2d::Identity();  // [cycles^2]
  if (ils.resolve(a, Q) != visors::nav::IlsStatus::kOk) {
    std::fprintf(stderr, "resolve failed\n");
    return 1;
  }
  const auto& s = ils.solution();
  const bool right = s.found >= 1 && s.a(0, 0) == 1.0 && s.a(1, 0) == -1.0;
  std::printf("visors_ambiguity alone: best candidate (%g, %g), ratio %.1f\n", s.a(0, 0), s.a(1, 0), s.ratio);
  return right ? 0 : 1;
}
