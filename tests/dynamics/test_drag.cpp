// Drag with a co-rotating atmosphere (M&G 2000 sec. 3.5.1).
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/dynamics/drag.hpp"

namespace {

using visors::core::kDegToRad;
using visors::core::StateVector;
using visors::dynamics::drag_acceleration;
using visors::dynamics::earth_rotation_gcrf_approximate;
using visors::dynamics::relative_wind_gcrf;

// brahe drag.rs::test_accel_drag (docs/algorithms/dynamics.md#drag-acceleration): a = R + 500 km
// (R = 6378136.3 m), e = 0.01, i = 97.3 deg, RAAN 15 deg, argp 30 deg, M 45 deg, GM = 3.986004415e14.
StateVector brahe_state() {
  visors::astro::KeplerianElements el;
  el.a = 6378136.3 + 500e3;
  el.e = 0.01;
  el.i = 97.3 * kDegToRad;
  el.raan = 15.0 * kDegToRad;
  el.argp = 30.0 * kDegToRad;
  el.M = 45.0 * kDegToRad;
  return visors::astro::cartesian_from_keplerian(el, 3.986004415e14);
}

TEST(Drag, BraheTestVectorMagnitude) {
  // rho = 1e-12 kg/m^3, m = 1000 kg, A = 1 m^2, C_D = 2, omega_E = 7.292115146706979e-5 rad/s:
  // |a| = 5.97601877277239e-8 m/s^2 (brahe; re-evaluated from M&G eq. 3.97 in
  // docs/algorithms/dynamics.md#drag-acceleration: 5.976018772772391e-8). Tolerance 1e-14
  // relative (measured 2e-16): the two element-to-Cartesian conversions round differently.
  const Eigen::Vector3d a =
      drag_acceleration(brahe_state(), 1e-12, 2.0, 1.0, 1000.0, earth_rotation_gcrf_approximate());
  EXPECT_NEAR(a.norm(), 5.97601877277239e-8, 1e-14 * 5.97601877277239e-8);
}

TEST(Drag, OpposesTheRelativeWind) {
  const StateVector x = brahe_state();
  const Eigen::Vector3d omega = earth_rotation_gcrf_approximate();
  const Eigen::Vector3d a = drag_acceleration(x, 1e-12, 2.0, 1.0, 1000.0, omega);
  const Eigen::Vector3d wind = relative_wind_gcrf(x, omega);
  // round-off of a unit-vector dot product; measured 0 (2026-11)
  EXPECT_NEAR(a.normalized().dot(wind.normalized()), -1.0, 1e-15);
}

TEST(Drag, RelativeWindSubtractsCoRotation) {
  // r on the x axis, omega on z: omega x r = (0, omega |r|, 0).
  StateVector x;
  x.r = Eigen::Vector3d(7e6, 0.0, 0.0);
  x.v = Eigen::Vector3d(0.0, 7500.0, 0.0);
  const Eigen::Vector3d wind = relative_wind_gcrf(x, earth_rotation_gcrf_approximate());
  EXPECT_DOUBLE_EQ(wind.y(), 7500.0 - visors::core::kEarthRotationRate * 7e6);
  EXPECT_EQ(wind.x(), 0.0);
  EXPECT_EQ(wind.z(), 0.0);
}

TEST(Drag, ScalesWithDensityAndBallisticCoefficient) {
  // a = -1/2 C_D (A/m) rho |v_r| v_r: linear in rho, C_D, A, 1/m.
  const StateVector x = brahe_state();
  const Eigen::Vector3d omega = earth_rotation_gcrf_approximate();
  const double a1 = drag_acceleration(x, 1e-12, 2.0, 1.0, 1000.0, omega).norm();
  const double a2 = drag_acceleration(x, 2e-12, 2.2, 3.0, 500.0, omega).norm();
  // round-off of a ratio of equal-formula values; measured 0 (2026-11)
  EXPECT_NEAR(a2 / a1, 2.0 * 1.1 * 3.0 * 2.0, 1e-13);
}

TEST(Drag, ZeroDensityGivesZero) {
  EXPECT_EQ(drag_acceleration(brahe_state(), 0.0, 2.0, 1.0, 1000.0, earth_rotation_gcrf_approximate())
                .norm(),
            0.0);
}

}  // namespace
