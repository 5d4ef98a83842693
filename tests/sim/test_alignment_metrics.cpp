// Alignment metrics against hand-computed geometry (Sun along +x).
#include <gtest/gtest.h>

#include "visors/sim/alignment_metrics.hpp"

namespace {

using visors::sim::add_alignment_sample;
using visors::sim::AlignmentRequirements;
using visors::sim::AlignmentResult;

const Eigen::Vector3d kSun = Eigen::Vector3d::UnitX();
const AlignmentRequirements kReq;

// OSC at (40.010, 0.003, -0.004) m from the DSC: focus error 10 mm, lateral error
// sqrt(3^2 + 4^2) = 5 mm; velocity (1e-3, 1e-4, 0): lateral 0.1 mm/s (the along-Sun part is free).
AlignmentResult one_sample() {
  AlignmentResult r;
  add_alignment_sample(r, Eigen::Vector3d(40.010, 0.003, -0.004), Eigen::Vector3d(1e-3, 1e-4, 0.0), Eigen::Vector3d::Zero(),
                       Eigen::Vector3d::Zero(), kSun, kReq);
  return r;
}

// loose: measured 0 (2026-11), bound 1e-12 m ~140x above round-off at 40 m (ulp 7.1e-15 m)
TEST(AlignmentMetrics, LateralErrorIsThePerpendicularDistance) { EXPECT_NEAR(one_sample().lateral_error_m, 0.005, 1e-12); }
// loose: measured 2.0e-15 m (2026-11), bound 1e-12 m ~500x above round-off of |r| - 40 m (ulp(40 m) 7.1e-15 m)
TEST(AlignmentMetrics, FocusErrorIsTheDistanceFrom40m) { EXPECT_NEAR(one_sample().focus_error_m, 0.010, 1e-12); }
// loose: measured 0 (2026-11), bound 1e-15 m/s ~5000x above round-off (ulp(1e-3 m/s) 2.2e-19)
TEST(AlignmentMetrics, LateralVelocityIgnoresTheSunLine) { EXPECT_NEAR(one_sample().lateral_velocity_mps, 1e-4, 1e-15); }
TEST(AlignmentMetrics, AllWithinRequirementsIsASuccess) { EXPECT_TRUE(one_sample().success(kReq)); }

// The worst sample of the window decides: a 20 mm lateral offset anywhere fails the attempt.
TEST(AlignmentMetrics, WorstSampleDecides) {
  AlignmentResult r = one_sample();
  add_alignment_sample(r, Eigen::Vector3d(40.0, 0.020, 0.0), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                       Eigen::Vector3d::Zero(), kSun, kReq);
  EXPECT_FALSE(r.success(kReq));
}

// The detector's frame (alignment_metrics.hpp): DSC at 7000 km along +y, Sun along +x, so x_det =
// +y (the vertical) and y_det = x_sun x x_det = +z; the OSC offset (40.010, 0.003, -0.004) m reads
// (0.003, -0.004) m laterally and +10 mm in focus.
AlignmentResult one_sample_in_orbit() {
  AlignmentResult r;
  const Eigen::Vector3d dsc(0.0, 7.0e6, 0.0);
  add_alignment_sample(r, dsc + Eigen::Vector3d(40.010, 0.003, -0.004), Eigen::Vector3d::Zero(), dsc, Eigen::Vector3d::Zero(),
                       kSun, kReq);
  return r;
}

// loose: bound 1e-9 m, round-off of 7e6 m positions (ulp 9.3e-10 m)
TEST(AlignmentMetrics, LateralErrorAlongTheVerticalIsTheDetectorsX) {
  EXPECT_NEAR(one_sample_in_orbit().lateral_detector_m.x(), 0.003, 2e-9);
}

TEST(AlignmentMetrics, LateralErrorAcrossIsTheDetectorsY) {
  EXPECT_NEAR(one_sample_in_orbit().lateral_detector_m.y(), -0.004, 2e-9);
}

TEST(AlignmentMetrics, FocusErrorKeepsItsSign) { EXPECT_NEAR(one_sample_in_orbit().focus_signed_m, 0.010, 2e-9); }

TEST(AlignmentMetrics, DetectorFrameExistsForADscAtTheOrigin) {
  EXPECT_NEAR(one_sample().lateral_detector_m.norm(), 0.005, 1e-12);  // any vertical: the length is kept
}

TEST(AlignmentMetrics, NoSampleIsNoSuccess) { EXPECT_FALSE(AlignmentResult{}.success(kReq)); }

}  // namespace
