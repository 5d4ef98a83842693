// The filter's mean propagation and transition (nav/orbit_time_update.hpp): the mean against the
// project's orbit propagator (dynamics::OrbitPropagator, RK4 on the same grid), the empirical
// acceleration's Gauss-Markov decay, and the short-step transition against central differences of
// the propagated mean (two-body, where the point-mass gradient is the exact one).
#include <gtest/gtest.h>

#include <cmath>

#include "visors/core/rtn_frame.hpp"
#include "visors/dynamics/orbit_propagator.hpp"
#include "visors/nav/orbit_time_update.hpp"

namespace visors::nav {
namespace {

core::GpsTime epoch() { return core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kGps).value(); }

dynamics::ForceModel model(dynamics::ForceModelConfig config) {
  dynamics::ForceModelData data;
  data.gravity_field = dynamics::embedded_gravity_field();
  auto m = dynamics::ForceModel::create(config, {}, std::move(data));
  EXPECT_TRUE(m.ok()) << m.error().describe();
  return std::move(m).value();
}

// 500 km, near-circular, sun-synchronous-like inclination.
core::StateVector leo() {
  const double r = 6878137.0;
  const double v = std::sqrt(3.986004415e14 / r);
  const double i = 97.4 * M_PI / 180.0;
  return {Eigen::Vector3d(r, 0.0, 0.0), Eigen::Vector3d(0.0, v * std::cos(i), v * std::sin(i))};
}

core::StateVector reference(dynamics::ForceModel& forces, const core::StateVector& x0, double dt) {
  dynamics::PropagatorSettings settings;
  settings.integrator = dynamics::IntegratorKind::kRk4Fixed;
  settings.step_s = 1.0;
  dynamics::OrbitPropagator propagator = dynamics::OrbitPropagator::create(forces, settings).value();
  return propagator.propagate_to(epoch(), x0, epoch() + dt).value();
}

// The on-board model (20x20 truncated to the embedded 8x8, drag, SRP, Sun, Moon), 10 s in 1 s
// steps: the same RK4 as the project's propagator, so equal to round-off.
TEST(OrbitTimeUpdate, MeanEqualsTheProjectPropagator) {
  dynamics::ForceModel forces = model(dynamics::ForceModelConfig::onboard());
  const MeanPropagation p = propagate_mean(forces, epoch(), leo(), Eigen::Vector3d::Zero(), 600.0, 10.0, 1.0);
  dynamics::ForceModel again = model(dynamics::ForceModelConfig::onboard());
  EXPECT_LT((p.x_gcrf.r - reference(again, leo(), 10.0).r).norm(), 1e-6);
}

// The short forecast (one evaluation, Taylor with the point-mass jerk) against the RK4 mean over
// 1 s with the on-board model and an empirical acceleration: measured 6.5e-6 m and 2.0e-5 m/s
// absolute (the J2 part of the jerk, ~0.4 % of G v, and the next order; the solution's own
// absolute error is ~1 m and 1.5 mm/s); between two spacecraft 40 m apart the errors cancel
// below 1e-9.
TEST(OrbitTimeUpdate, ShortForecastMatchesTheRk4Mean) {
  const Eigen::Vector3d a_rtn(2e-7, -5e-7, 3e-7);
  dynamics::ForceModel forces = model(dynamics::ForceModelConfig::onboard());
  const core::StateVector chief = leo();
  core::StateVector deputy = chief;
  deputy.r += Eigen::Vector3d(3.0, -39.0, 8.0);
  deputy.v += Eigen::Vector3d(0.01, 0.002, -0.03);
  const auto rk4 = [&](const core::StateVector& x) { return propagate_mean(forces, epoch(), x, a_rtn, 600.0, 1.0, 1.0).x_gcrf; };
  const auto taylor = [&](const core::StateVector& x) {
    return forecast_mean(forces, epoch(), x, a_rtn, 600.0, 1.0, forces.gm()).x_gcrf;
  };
  const core::StateVector c_rk4 = rk4(chief), c_taylor = taylor(chief);
  const core::StateVector d_rk4 = rk4(deputy), d_taylor = taylor(deputy);
  EXPECT_LT((c_taylor.r - c_rk4.r).norm(), 1e-5);
  EXPECT_LT((c_taylor.v - c_rk4.v).norm(), 3e-5);
  EXPECT_LT(((d_taylor.r - c_taylor.r) - (d_rk4.r - c_rk4.r)).norm(), 1e-9);
  EXPECT_LT(((d_taylor.v - c_taylor.v) - (d_rk4.v - c_rk4.v)).norm(), 1e-9);
}

// With tau = 1e15 s the empirical acceleration is constant: the propagator with that constant
// RTN acceleration in its configuration.
TEST(OrbitTimeUpdate, ConstantEmpiricalAccelerationAsTheConfiguredOne) {
  const Eigen::Vector3d a_rtn(2e-7, -5e-7, 3e-7);
  dynamics::ForceModel forces = model(dynamics::ForceModelConfig::gravity_only(8, 8));
  const MeanPropagation p = propagate_mean(forces, epoch(), leo(), a_rtn, 1e15, 10.0, 1.0);
  dynamics::ForceModelConfig c = dynamics::ForceModelConfig::gravity_only(8, 8);
  c.empirical_rtn = a_rtn;
  dynamics::ForceModel constant = model(c);
  EXPECT_LT((p.x_gcrf.r - reference(constant, leo(), 10.0).r).norm(), 1e-9);
}

TEST(OrbitTimeUpdate, EmpiricalAccelerationDecaysWithTau) {
  dynamics::ForceModel forces = model(dynamics::ForceModelConfig::gravity_only(0, 0));
  const MeanPropagation p = propagate_mean(forces, epoch(), leo(), Eigen::Vector3d(1e-6, 0, 0), 600.0, 30.0, 10.0);
  EXPECT_DOUBLE_EQ(p.a_emp_rtn_mps2(0), 1e-6 * std::exp(-30.0 / 600.0));
}

// Columns of the transition against central differences of the propagated mean, two-body, over
// 10 s (steps 10 m, 1 m/s, 1e-3 m/s^2: the position's round-off, 7e-10 m, stays below 1e-9 of
// each column). The form neglects terms of order (G dt^2)^2 ~ 1e-8 and the change of G beyond
// linear: 1e-8 relative for the position and velocity columns. The empirical-acceleration columns
// take the RTN frame's turn as linear (its quadratic part, n^2 dt^4/24 = 5e-4 s^2 of 50 s^2 over
// 10 s; 5e-8 of 0.5 over the filter's 1 s): 2e-5 of the column's norm.
TEST(OrbitTimeUpdate, TransitionMatchesCentralDifferences) {
  const double dt = 10.0, tau = 600.0;
  const core::StateVector x0 = leo();
  dynamics::ForceModel two_body = model(dynamics::ForceModelConfig::gravity_only(0, 0));
  const core::StateVector x1 = propagate_mean(two_body, epoch(), x0, Eigen::Vector3d::Zero(), tau, dt, 1.0).x_gcrf;
  const DynamicTransition phi = dynamic_transition(x0, x1, two_body.gm(), dt, tau);
  const double steps[3] = {10.0, 1.0, 1e-3};
  for (int j = 0; j < 9; ++j) {
    const double h = steps[j / 3];
    auto run = [&](double sign) {
      core::StateVector x = x0;
      Eigen::Vector3d a = Eigen::Vector3d::Zero();
      if (j < 3) x.r(j) += sign * h;
      else if (j < 6) x.v(j - 3) += sign * h;
      else a(j - 6) += sign * h;
      dynamics::ForceModel forces = model(dynamics::ForceModelConfig::gravity_only(0, 0));
      const MeanPropagation p = propagate_mean(forces, epoch(), x, a, tau, dt, 1.0);
      Eigen::Matrix<double, 9, 1> y;
      y << p.x_gcrf.r, p.x_gcrf.v, p.a_emp_rtn_mps2;
      return y;
    };
    const Eigen::Matrix<double, 9, 1> numeric = (run(1.0) - run(-1.0)) / (2.0 * h);
    for (int i = 0; i < 9; ++i) {
      const double tolerance = j < 6 ? 1e-8 * (1.0 + std::abs(numeric(i))) : 2e-5 * numeric.norm();
      EXPECT_NEAR(phi(i, j), numeric(i), tolerance) << "row " << i << " column " << j;
    }
  }
}

// The empirical-acceleration columns are rotated from RTN: an along-track acceleration moves the
// position along the velocity.
TEST(OrbitTimeUpdate, AlongTrackEmpiricalAccelerationMovesAlongTrack) {
  const core::StateVector x0 = leo();
  const DynamicTransition phi = dynamic_transition(x0, x0, 3.986004415e14, 10.0, 600.0);
  const Eigen::Vector3d along = core::gcrf_to_rtn_matrix(x0).row(1).transpose();
  const Eigen::Vector3d column = phi.block<3, 1>(0, 7).normalized();
  EXPECT_NEAR(column.dot(along), 1.0, 1e-12);
}

}  // namespace
}  // namespace visors::nav
