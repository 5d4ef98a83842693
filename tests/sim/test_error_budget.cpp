// The error budget of an attempt (sim/error_budget.hpp): its terms add up to the true error, each
// term's sign, and the Hill-Clohessy-Wiltshire impulse response against a numerical integration of
// the HCW equations (Clohessy & Wiltshire 1960: x'' = 3 n^2 x + 2 n y', y'' = -2 n x',
// z'' = -n^2 z; x radial, y along-track, z normal).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "visors/sim/error_budget.hpp"

namespace {

using visors::core::StateVector;
using visors::sim::BudgetInputs;
using visors::sim::BudgetTerm;
using visors::sim::ErrorBudget;

Eigen::Vector3d random_vector(std::mt19937_64& rng, double scale) {
  std::normal_distribution<double> g(0.0, scale);
  return {g(rng), g(rng), g(rng)};
}

BudgetInputs random_inputs(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  BudgetInputs in;
  in.target_true = Eigen::Vector3d(0.3, -0.8, 0.5).normalized();
  in.target_estimated = (in.target_true + random_vector(rng, 1e-5)).normalized();
  in.com_true = {40.0 * in.target_true + random_vector(rng, 0.02), random_vector(rng, 1e-4)};
  in.payload_true = {in.com_true.r + random_vector(rng, 0.005), in.com_true.v};
  in.com_estimated = {in.com_true.r + random_vector(rng, 0.01), in.com_true.v + random_vector(rng, 5e-5)};
  in.lever_error = random_vector(rng, 0.005);
  in.last_burn = {random_vector(rng, 0.003), random_vector(rng, 2e-5)};
  in.drag_prediction = {random_vector(rng, 0.004), random_vector(rng, 3e-5)};
  in.dsc_position = Eigen::Vector3d(6.9e6, 1.0e5, -2.0e5);
  return in;
}

// The detector frame of sim/alignment_metrics.cpp, written out again.
struct Frame {
  Eigen::Vector3d x, y, z;
};
Frame frame_of(const BudgetInputs& in) {
  const Eigen::Vector3d& s = in.target_true;
  const Eigen::Vector3d x = (in.dsc_position - in.dsc_position.dot(s) * s).normalized();
  return {x, s.cross(x), s};
}

double sum_of(const ErrorBudget& b, double visors::sim::BudgetComponents::*field) {
  double sum = 0.0;
  for (const auto& c : b) sum += c.*field;
  return sum;
}

TEST(ErrorBudget, TermsAddUpToTheLateralX) {
  const BudgetInputs in = random_inputs(1);
  const Frame f = frame_of(in);
  const Eigen::Vector3d error = in.payload_true.r - in.focal_distance_m * in.target_true;
  EXPECT_NEAR(sum_of(visors::sim::error_budget(in), &visors::sim::BudgetComponents::x_m), error.dot(f.x), 1e-12);
}

TEST(ErrorBudget, TermsAddUpToTheLateralY) {
  const BudgetInputs in = random_inputs(2);
  const Frame f = frame_of(in);
  const Eigen::Vector3d error = in.payload_true.r - in.focal_distance_m * in.target_true;
  EXPECT_NEAR(sum_of(visors::sim::error_budget(in), &visors::sim::BudgetComponents::y_m), error.dot(f.y), 1e-12);
}

TEST(ErrorBudget, TermsAddUpToTheFocus) {
  const BudgetInputs in = random_inputs(3);
  const Eigen::Vector3d error = in.payload_true.r - in.focal_distance_m * in.target_true;
  EXPECT_NEAR(sum_of(visors::sim::error_budget(in), &visors::sim::BudgetComponents::focus_m), error.dot(in.target_true), 1e-12);
}

TEST(ErrorBudget, VelocityTermsAddUpToTheLateralVelocity) {
  const BudgetInputs in = random_inputs(4);
  const Frame f = frame_of(in);
  EXPECT_NEAR(sum_of(visors::sim::error_budget(in), &visors::sim::BudgetComponents::velocity_y_mps), in.payload_true.v.dot(f.y),
              1e-15);
}

// An estimate 1 cm too far along y puts the control's aim 1 cm short there: the navigation term is
// -1 cm in y (the control term, which sees the estimate, +1 cm).
TEST(ErrorBudget, NavigationTermIsTheEstimateErrorReversed) {
  BudgetInputs in = random_inputs(5);
  in.com_estimated = in.com_true;
  in.lever_error.setZero();
  in.com_estimated.r += 0.01 * frame_of(in).y;
  EXPECT_NEAR(visors::sim::error_budget(in)[static_cast<std::size_t>(BudgetTerm::kNavigation)].y_m, -0.01, 1e-12);
}

// RK4 of the HCW equations at 0.1 s from (0, dv).
StateVector integrate_hcw(const Eigen::Vector3d& dv, double n, double t) {
  using V6 = Eigen::Matrix<double, 6, 1>;
  const auto f = [n](const V6& s) {
    V6 d;
    d << s.tail<3>(), 3.0 * n * n * s(0) + 2.0 * n * s(4), -2.0 * n * s(3), -n * n * s(2);
    return d;
  };
  V6 s;
  s << Eigen::Vector3d::Zero(), dv;
  const double h = 0.1;
  for (double time = 0.0; time < t - 1e-9; time += h) {
    const V6 k1 = f(s), k2 = f(s + 0.5 * h * k1), k3 = f(s + 0.5 * h * k2), k4 = f(s + h * k3);
    s += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return {s.head<3>(), s.tail<3>()};
}

constexpr double kMeanMotion = 1.107e-3;  // [rad/s], 500 km

TEST(HcwImpulseResponse, PositionMatchesTheIntegratedEquations) {
  const Eigen::Vector3d dv(1e-4, -2e-4, 5e-5);
  const StateVector expected = integrate_hcw(dv, kMeanMotion, 900.0);
  EXPECT_LT((visors::sim::hcw_impulse_response(dv, kMeanMotion, 900.0).r - expected.r).norm(), 1e-9);
}

TEST(HcwImpulseResponse, VelocityMatchesTheIntegratedEquations) {
  const Eigen::Vector3d dv(1e-4, -2e-4, 5e-5);
  const StateVector expected = integrate_hcw(dv, kMeanMotion, 900.0);
  EXPECT_LT((visors::sim::hcw_impulse_response(dv, kMeanMotion, 900.0).v - expected.v).norm(), 1e-12);
}

}  // namespace
