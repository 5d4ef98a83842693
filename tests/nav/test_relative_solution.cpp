// The filter's relative output (nav/relative_solution.hpp): the relative state against
// core::relative_state_rtn, and the covariance's Jacobian against central differences of that
// function in every scaled state.
#include <gtest/gtest.h>

#include <cmath>

#include "visors/nav/relative_solution.hpp"

namespace visors::nav {
namespace {

NavVector state_vector() {
  NavVector x = NavVector::Zero();
  const double r = 6878137.0, v = std::sqrt(3.986004415e14 / r);
  x.segment<3>(state::position(Craft::kDsc)) = Eigen::Vector3d(r, 0.0, 0.0);
  x.segment<3>(state::velocity(Craft::kDsc)) = Eigen::Vector3d(0.0, 0.13 * v, 0.99 * v) / state::kVelocityUnit;
  x.segment<3>(state::position(Craft::kOsc)) = Eigen::Vector3d(r + 5.0, 30.0, -25.0);
  x.segment<3>(state::velocity(Craft::kOsc)) = Eigen::Vector3d(0.02, 0.13 * v - 0.01, 0.99 * v + 0.005) / state::kVelocityUnit;
  return x;
}

Eigen::Matrix<double, 6, 1> relative(const NavVector& x) {
  const RelativeSolution s = relative_solution({}, x, NavMatrix::Identity());
  Eigen::Matrix<double, 6, 1> y;
  y << s.relative.dr_rtn, s.relative.dv_rtn;
  return y;
}

TEST(RelativeSolution, RelativeStateIsTheProjectsRtnState) {
  const NavVector x = state_vector();
  const RelativeSolution s = relative_solution({}, x, NavMatrix::Identity());
  const core::RelativeStateRtn expected = core::relative_state_rtn(s.dsc_gcrf, s.osc_gcrf);
  EXPECT_LT((s.relative.dv_rtn - expected.dv_rtn).norm(), 1e-15);
}

// P = e_i e_i' picks column i of J: J P J' = J_i J_i', against the outer product of the central
// difference of the relative state in state i (steps 1 m, 1 mm/s = 1 state unit). The DSC's own
// frame dependence is left out by design (header): its columns of the chief's position and
// velocity differ by separation / radius (6e-6 relative), hence the tolerance 1e-5.
TEST(RelativeSolution, CovarianceMapsThroughTheRelativeStatesJacobian) {
  const NavVector x = state_vector();
  for (int i = 0; i < kNavStates; ++i) {
    NavMatrix P = NavMatrix::Zero();
    P(i, i) = 1.0;
    const Eigen::Matrix<double, 6, 6> C = relative_solution({}, x, P).covariance_rtn;
    NavVector plus = x, minus = x;
    plus(i) += 1.0;
    minus(i) -= 1.0;
    const Eigen::Matrix<double, 6, 1> column = (relative(plus) - relative(minus)) / 2.0;
    const Eigen::Matrix<double, 6, 6> expected = column * column.transpose();  // signs included
    EXPECT_LE((C - expected).norm(), 1e-5 * (1.0 + expected.norm())) << "state " << i;
  }
}

}  // namespace
}  // namespace visors::nav
