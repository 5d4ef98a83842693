// The laser-rangefinder model (nav/laser_range_model.hpp): its value against the geometry, its
// row against central differences (docs/algorithms/cdgps-filter.md#laser-rangefinder).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "visors/nav/laser_range_model.hpp"

namespace visors::nav {
namespace {

NavVector state_vector() {
  NavVector x = NavVector::Zero();
  x.segment<3>(state::position(Craft::kDsc)) = Eigen::Vector3d(6878137.0, 0.0, 0.0);
  x.segment<3>(state::position(Craft::kOsc)) = Eigen::Vector3d(6878139.0, -39.5, 3.0);
  return x;
}

LaserRangeGeometry geometry() {
  LaserRangeGeometry g;
  g.dsc_body_to_gcrf = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  g.osc_body_to_gcrf = Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  g.dsc_lever_body_m = Eigen::Vector3d(-0.15, 0.02, 0.0);
  g.osc_lever_body_m = Eigen::Vector3d(0.15, 0.0, 0.01);
  g.bias_m = 0.004;
  return g;
}

// Zero-noise truth: the value is the distance of the two optical points plus the bias.
TEST(LaserRangeModel, ValueIsTheOpticalPointsDistancePlusBias) {
  const NavVector x = state_vector();
  const LaserRangeGeometry g = geometry();
  const Eigen::Vector3d p_dsc = x.segment<3>(state::position(Craft::kDsc)) + g.dsc_body_to_gcrf * g.dsc_lever_body_m;
  const Eigen::Vector3d p_osc = x.segment<3>(state::position(Craft::kOsc)) + g.osc_body_to_gcrf * g.osc_lever_body_m;
  EXPECT_NEAR(predict_laser_range(x, g).value_m, (p_dsc - p_osc).norm() + 0.004, 1e-9);
}

// Central differences, 1 cm steps (the range's curvature over 40 m: 1e-2^2/40 = 2.5e-6 m).
TEST(LaserRangeModel, RowMatchesCentralDifferences) {
  const NavVector x = state_vector();
  const NavRow h = predict_laser_range(x, geometry()).h;
  for (int i = 0; i < kNavStates; ++i) {
    NavVector plus = x, minus = x;
    plus(i) += 0.01;
    minus(i) -= 0.01;
    const double numeric = (predict_laser_range(plus, geometry()).value_m - predict_laser_range(minus, geometry()).value_m) / 0.02;
    EXPECT_NEAR(h(i), numeric, 1e-6) << "state " << i;
  }
}

}  // namespace
}  // namespace visors::nav
