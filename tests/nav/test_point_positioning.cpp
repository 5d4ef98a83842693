// Single-point positioning (nav/point_positioning.hpp) on the synthetic constellation
// (support/synthetic_gps.hpp): from the Earth's centre to the receiver within the code noise's
// reach, and its refusals.
#include <gtest/gtest.h>

#include <random>

#include "visors/gnss/ephemeris_set.hpp"
#include "visors/nav/point_positioning.hpp"
#include "support/synthetic_gps.hpp"

namespace visors::nav {
namespace {

core::GpsTime epoch() { return core::GpsTime::parse("2024-10-01T00:30:00", core::TimeScale::kGps).value(); }

struct Scene {
  std::vector<gnss::BroadcastEphemeris> records = test::synthetic_constellation(epoch());
  gnss::EphemerisSet ephemerides = gnss::EphemerisSet::screen(records);
  core::OnboardEarthFrame frame;
  ReceiverEstimate truth{Eigen::Vector3d(1.2e6, -6.1e6, 2.9e6).normalized() * 6878137.0, Eigen::Vector3d::Zero(), 4.2e4,
                         Eigen::Vector3d::Zero()};
  std::vector<double> integers = std::vector<double>(33, 0.0);
  std::mt19937_64 rng{3};

  GpsReceiverEpoch observe(double code_sigma_m) {
    return test::synthetic_observations(epoch(), truth, records, frame, integers, 0.0, code_sigma_m, 0.0, rng);
  }
};

// 20 cm code noise and ~10 satellites: a position within ~1 m (PDOP ~2 x 0.2 m x margin).
TEST(PointPositioning, ReachesTheReceiverFromTheEarthsCentre) {
  Scene s;
  const PointSolution p = solve_point_position(s.observe(0.2), s.ephemerides, s.frame, Eigen::Vector3d::Zero());
  ASSERT_TRUE(p.ok) << p.reason;
  EXPECT_LT((p.r_gcrf_m - s.truth.r_gcrf_m).norm(), 1.0);
}

TEST(PointPositioning, SolvesTheClock) {
  Scene s;
  const PointSolution p = solve_point_position(s.observe(0.2), s.ephemerides, s.frame, Eigen::Vector3d::Zero());
  EXPECT_NEAR(p.clock_m, s.truth.clock_m, 1.0);
}

// Without noise the solution is the truth to the model's round-off.
TEST(PointPositioning, ExactWithoutNoise) {
  Scene s;
  const PointSolution p = solve_point_position(s.observe(0.0), s.ephemerides, s.frame, Eigen::Vector3d::Zero());
  EXPECT_LT((p.r_gcrf_m - s.truth.r_gcrf_m).norm(), 1e-4);
}

TEST(PointPositioning, RefusesFourSatellites) {
  Scene s;
  GpsReceiverEpoch e = s.observe(0.2);
  e.count = 4;
  const PointSolution p = solve_point_position(e, s.ephemerides, s.frame, Eigen::Vector3d::Zero());
  EXPECT_STREQ(p.reason, "too_few_satellites");
}

// A 1 km blunder on one pseudorange cannot hide in the residuals.
TEST(PointPositioning, RefusesABlunder) {
  Scene s;
  GpsReceiverEpoch e = s.observe(0.2);
  e.observations[2].code_m += 1000.0;
  const PointSolution p = solve_point_position(e, s.ephemerides, s.frame, Eigen::Vector3d::Zero());
  EXPECT_STREQ(p.reason, "residuals");
}

}  // namespace
}  // namespace visors::nav
