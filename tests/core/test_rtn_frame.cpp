// RTN frame: sign conventions (docs/conventions.md), inverse, circular-orbit kinematics.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "visors/core/rtn_frame.hpp"

namespace {

using visors::core::RelativeStateRtn;
using visors::core::StateVector;

constexpr double kMu = 3.986004415e14;  // [m^3/s^2]

// Circular equatorial chief at radius a, prograde: at phase u the position is a (cos u, sin u, 0).
StateVector circular(double a, double u) {
  const double v = std::sqrt(kMu / a);
  return {{a * std::cos(u), a * std::sin(u), 0.0}, {-v * std::sin(u), v * std::cos(u), 0.0}};
}

// A general chief: inclined, eccentric-looking state (r and v not perpendicular).
StateVector general_chief() {
  return {{-4.2e6, 5.1e6, 1.9e6}, {-5.4e3, -3.1e3, 4.4e3}};
}

TEST(RtnFrame, AxesOfACircularEquatorialOrbit) {
  const Eigen::Matrix3d m = visors::core::gcrf_to_rtn_matrix(circular(7e6, 0.0));
  // round-off of unit vectors (ulp 1.1e-16); measured 0 / 6.1e-17 (2026-11)
  EXPECT_LT((m - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-15);  // R=x, T=y, N=z
  const Eigen::Matrix3d m90 = visors::core::gcrf_to_rtn_matrix(circular(7e6, M_PI / 2));
  EXPECT_LT((m90.row(0) - Eigen::RowVector3d(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((m90.row(1) - Eigen::RowVector3d(-1, 0, 0)).norm(), 1e-15);
}

TEST(RtnFrame, SignConventions) {
  const double a = 6878137.0;
  const StateVector chief = circular(a, 0.3);
  // Deputy ahead along-track (larger phase on the same circle): +T, and R slightly negative (the
  // chord dips below the chief's local horizontal).
  const StateVector ahead = circular(a, 0.3 + 100.0 / a);
  const auto rel_ahead = visors::core::relative_state_rtn(chief, ahead);
  // loose: chord vs arc gives 100 - s^3/(6 a^2) = 100 - 3.5e-9 m; measured 3.7e-9 m (2026-11), bound 1e-4 ~3e4x above
  EXPECT_NEAR(rel_ahead.dr_rtn.y(), 100.0, 1e-4);
  EXPECT_LT(rel_ahead.dr_rtn.x(), 0.0);
  // On the same circular orbit the deputy is at rest in the chief's RTN.
  // loose: measured 6.5e-13 m/s (2026-11), bound 1e-9 ~1500x above round-off (ulp(v) 9e-13)
  EXPECT_LT(rel_ahead.dv_rtn.norm(), 1e-9);
  // Deputy higher (same direction, larger radius): +R.
  StateVector higher = chief;
  higher.r *= (a + 50.0) / a;
  // round-off: ulp(|r| = 6.9e6 m) = 9.3e-10 m; measured 3.9e-10 m (2026-11)
  EXPECT_NEAR(visors::core::relative_state_rtn(chief, higher).dr_rtn.x(), 50.0, 1e-8);
  // Deputy displaced along the angular momentum: +N.
  StateVector north = chief;
  north.r.z() += 20.0;
  // round-off (ulp 9.3e-10 m); measured 0 (2026-11)
  EXPECT_NEAR(visors::core::relative_state_rtn(chief, north).dr_rtn.z(), 20.0, 1e-9);
  // Deputy faster along-track: +T relative velocity (minus the frame's rotation of dr = 0).
  StateVector faster = chief;
  faster.v += 0.01 * chief.v.normalized();
  // round-off: ulp(|v| = 7.6e3 m/s) = 9.1e-13; measured 3.3e-13 m/s (2026-11)
  EXPECT_NEAR(visors::core::relative_state_rtn(chief, faster).dv_rtn.y(), 0.01, 1e-12);
}

TEST(RtnFrame, RotatingFrameVelocityOfAStaticInertialOffset) {
  // A deputy with the chief's velocity but displaced +R by 10 m is, in the rotating frame,
  // drifting at -omega x dr = -n * 10 m along T (n = |v|/a for a circular orbit).
  const double a = 7e6;
  const StateVector chief = circular(a, 1.0);
  StateVector deputy = chief;
  deputy.r += 10.0 * chief.r.normalized();
  const auto rel = visors::core::relative_state_rtn(chief, deputy);
  const double n = std::sqrt(kMu / (a * a * a));
  // round-off: n * 10 m from 7e6 m positions; measured 1.7e-13 / 2.8e-13 m/s (2026-11)
  EXPECT_NEAR(rel.dv_rtn.y(), -n * 10.0, 1e-12);
  EXPECT_NEAR(rel.dv_rtn.x(), 0.0, 1e-12);
}

TEST(RtnFrame, MatrixIsARotationWithTheStatedRows) {
  const StateVector c = general_chief();
  const Eigen::Matrix3d m = visors::core::gcrf_to_rtn_matrix(c);
  // round-off of unit vectors (ulp 1.1e-16); measured <= 3.3e-16 (2026-11)
  EXPECT_LT((m * m.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(m.determinant(), 1.0, 1e-15);
  EXPECT_LT((m.row(0).transpose() - c.r.normalized()).norm(), 1e-15);
  EXPECT_LT((m.row(2).transpose() - c.r.cross(c.v).normalized()).norm(), 1e-15);
  EXPECT_GT(m.row(1).dot(c.v), 0.0);  // T points along the motion
}

TEST(RtnFrame, InverseRoundTrip) {
  const StateVector chief = general_chief();
  const StateVector deputy{chief.r + Eigen::Vector3d(12.0, -30.0, 25.0),
                           chief.v + Eigen::Vector3d(0.02, 0.01, -0.03)};
  const RelativeStateRtn rel = visors::core::relative_state_rtn(chief, deputy);
  const StateVector back = visors::core::deputy_state_gcrf(chief, rel);
  // round-off of |r| = 7e6 m, |v| = 7.5e3 m/s (ulp 9.3e-10, 9.1e-13); measured 0 (2026-11)
  EXPECT_LT((back.r - deputy.r).norm(), 1e-8);
  EXPECT_LT((back.v - deputy.v).norm(), 1e-12);
  // And the other way.
  const RelativeStateRtn given{{40.0, -5.0, 3.0}, {0.001, -0.002, 0.0005}};
  const RelativeStateRtn again =
      visors::core::relative_state_rtn(chief, visors::core::deputy_state_gcrf(chief, given));
  // round-off (ulp 9.3e-10 m, 9.1e-13 m/s); measured 3.5e-10 m, 6.4e-13 m/s (2026-11)
  EXPECT_LT((again.dr_rtn - given.dr_rtn).norm(), 1e-8);
  EXPECT_LT((again.dv_rtn - given.dv_rtn).norm(), 1e-12);
}

TEST(RtnFrame, RotatingFrameVelocityIsTheDerivativeOfRtnPosition) {
  // Two Keplerian circular orbits with different radius/phase: d/dt of dr_rtn by central
  // differences equals dv_rtn (the frame's rate (r x v)/|r|^2 is exact for Keplerian motion).
  const double a = 6878137.0;
  const auto states = [&](double t) {
    const double nc = std::sqrt(kMu / (a * a * a));
    const double ad = a + 200.0;
    const double nd = std::sqrt(kMu / (ad * ad * ad));
    return std::pair{circular(a, nc * t), circular(ad, 1e-5 + nd * t)};
  };
  const double h = 0.5;
  const auto rel_at = [&](double t) {
    const auto [c, d] = states(t);
    return visors::core::relative_state_rtn(c, d);
  };
  const Eigen::Vector3d dr_dot = (rel_at(100.0 + h).dr_rtn - rel_at(100.0 - h).dr_rtn) / (2 * h);
  // analytic: truncation h^2/6 |d3r/dt3| ~1e-8 m/s plus round-off ulp(7e6 m)/2h ~1e-9 m/s; measured 3.7e-10 m/s (2026-11)
  EXPECT_LT((dr_dot - rel_at(100.0).dv_rtn).norm(), 1e-7);
}

TEST(RtnFrame, AngularVelocityOfACircularOrbitIsTheMeanMotion) {
  const double a = 7e6;
  const Eigen::Vector3d w = visors::core::rtn_angular_velocity_gcrf(circular(a, 2.0));
  // round-off (ulp(n) 2e-19); measured 0 (2026-11)
  EXPECT_NEAR(w.z(), std::sqrt(kMu / (a * a * a)), 1e-15);
  EXPECT_NEAR(w.head<2>().norm(), 0.0, 1e-18);
}

}  // namespace
