#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Geometry>

#include "visors/core/constants.hpp"
#include "visors/sim/attitude_profile.hpp"

namespace {

using visors::core::kDegToRad;
using visors::sim::AttitudeProfile;
using visors::sim::AttitudeSettings;
using visors::sim::ObservationWindow;
using visors::sim::rotation_angle_rad;

// Circular two-body test orbit: a = R_E + 500 km, i = 97.8 deg, RAAN = 157.5 deg (mission chief,
// docs/conventions.md), mu of GGM05S; Sun direction fixed (test choice, off the orbit plane).
struct Orbit {
  double a = 6378136.3 + 500e3;
  double n = std::sqrt(3.986004415e14 / (a * a * a));
  Eigen::Matrix3d plane = (Eigen::AngleAxisd(157.5 * kDegToRad, Eigen::Vector3d::UnitZ()) *
                           Eigen::AngleAxisd(97.8 * kDegToRad, Eigen::Vector3d::UnitX()))
                              .toRotationMatrix();
  Eigen::Vector3d sun = Eigen::Vector3d(0.6, -0.7, 0.39).normalized();

  [[nodiscard]] Eigen::Vector3d r(double t) const { return plane * Eigen::Vector3d(std::cos(n * t), std::sin(n * t), 0.0) * a; }
  [[nodiscard]] Eigen::Vector3d v(double t) const {
    return plane * Eigen::Vector3d(-std::sin(n * t), std::cos(n * t), 0.0) * (a * n);
  }
};

AttitudeProfile make_profile() {
  auto p = AttitudeProfile::create();
  EXPECT_TRUE(p.ok());
  return std::move(p).value();
}

Eigen::Quaterniond attitude(const AttitudeProfile& p, const Orbit& o, double t) {
  return p.body_to_gcrf(t, o.r(t), o.v(t), o.sun);
}

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Observation at start_s = 1500 s, 300 s long. The slew is commanded required_slew_lead_s(angle)
// before start_s, with angle = the rotation from the nominal attitude at the slew start to the
// observation attitude at start_s - settling (three substitutions: the slew start depends on it).
struct Scenario {
  Orbit orbit;
  AttitudeProfile profile = make_profile();
  ObservationWindow window;
  Scenario() {
    const double start = 1500.0, arrival = start - profile.settings().settling_s;
    const Eigen::Quaterniond q_target =
        AttitudeProfile::observation_body_to_gcrf(orbit.r(arrival), orbit.v(arrival), orbit.sun);
    double slew_start = start - 90.0;
    for (int k = 0; k < 3; ++k) {
      const double angle = rotation_angle_rad(
          AttitudeProfile::nominal_body_to_gcrf(orbit.r(slew_start), orbit.v(slew_start), orbit.sun), q_target);
      slew_start = start - profile.required_slew_lead_s(angle);
    }
    window = {slew_start, start, start + 300.0};
    EXPECT_TRUE(profile.schedule(window).ok());
  }
};

TEST(AttitudeProfile, DefaultSettingsAreValid) { EXPECT_TRUE(AttitudeSettings{}.validate().ok()); }

TEST(AttitudeProfile, RejectsNonPositiveRate) {
  AttitudeSettings s;
  s.slew_rate_radps = 0.0;
  EXPECT_EQ(AttitudeProfile::create(s).error().field, "slew_rate_radps");
}

TEST(AttitudeProfile, ScheduleRejectsSlewAfterStart) {
  AttitudeProfile p = make_profile();
  EXPECT_EQ(p.schedule({100.0, 50.0, 200.0}).error().field, "slew_start_s");
}

TEST(AttitudeProfile, ScheduleRejectsEndBeforeStart) {
  AttitudeProfile p = make_profile();
  EXPECT_EQ(p.schedule({0.0, 50.0, 40.0}).error().field, "end_s");
}

TEST(AttitudeProfile, ScheduleRejectsOverlap) {
  AttitudeProfile p = make_profile();
  ASSERT_TRUE(p.schedule({0.0, 100.0, 200.0}).ok());
  EXPECT_EQ(p.schedule({150.0, 300.0, 400.0}).error().field, "slew_start_s");
}

// 90 deg at 1.5 deg/s = 60 s; plus 30 s settling = 90 s (the defaults, by hand).
TEST(AttitudeProfile, SlewDurationIsAngleOverRate) {
  // loose: measured 7.1e-15 s (2026-11), bound 1e-12 s ~140x above round-off (ulp(60 s) 7.1e-15 s)
  EXPECT_NEAR(make_profile().slew_duration_s(90.0 * kDegToRad), 60.0, 1e-12);
}

TEST(AttitudeProfile, LeadTimeAddsSettling) {
  // round-off (ulp(90 s) 1.4e-14 s); measured 0 (2026-11)
  EXPECT_NEAR(make_profile().required_slew_lead_s(90.0 * kDegToRad), 90.0, 1e-12);
}

// Nominal attitude: +Z on the zenith (definition), angle < 1e-12 rad.
TEST(AttitudeProfile, NominalPutsAntennaOnZenith) {
  const Orbit o;
  const AttitudeProfile p = make_profile();
  for (double t = 0.0; t < 6000.0; t += 250.0) {
    // definition (comment above); loose: measured <= 3.7e-16 rad (2026-11), bound 1e-12 rad ~3000x above round-off
    ASSERT_LT(visors::sim::antenna_off_zenith_rad(attitude(p, o, t), o.r(t)), 1e-12) << t;
  }
}

// Nominal attitude: +X is the Sun projected on the local horizontal plane (definition).
TEST(AttitudeProfile, NominalPutsPayloadAxisTowardsTheProjectedSun) {
  const Orbit o;
  const Eigen::Vector3d z = o.r(700.0).normalized();
  const Eigen::Vector3d x = attitude(make_profile(), o, 700.0) * Eigen::Vector3d::UnitX();
  // definition (comment above); loose: measured 1.3e-16 rad (2026-11), bound 1e-12 rad ~7500x above round-off
  EXPECT_LT(angle_between(x, (o.sun - o.sun.dot(z) * z)), 1e-12);
}

// Observation attitude: +X on the Sun (definition), angle < 1e-12 rad, during the hold.
TEST(AttitudeProfile, ObservationPutsPayloadAxisOnTheSun) {
  const Scenario s;
  for (double t = s.window.start_s; t <= s.window.end_s; t += 20.0) {
    // definition (comment above); loose: measured <= 3.3e-16 rad (2026-11), bound 1e-12 rad ~3000x above round-off
    ASSERT_LT(angle_between(attitude(s.profile, s.orbit, t) * Eigen::Vector3d::UnitX(), s.orbit.sun), 1e-12) << t;
  }
}

// Observation attitude: the antenna is as close to zenith as +X on the Sun allows. Z is then the
// zenith's component normal to the Sun, so its angle from the zenith is |pi/2 - angle(Sun, zenith)|
// (plane geometry, hand).
TEST(AttitudeProfile, ObservationKeepsAntennaClosestToZenith) {
  const Scenario s;
  const double t = s.window.start_s + 100.0;
  const double sun_zenith = angle_between(s.orbit.sun, s.orbit.r(t));
  // plane geometry (comment above); loose: measured 1.1e-16 rad (2026-11), bound 1e-12 rad ~9000x above round-off
  EXPECT_NEAR(visors::sim::antenna_off_zenith_rad(attitude(s.profile, s.orbit, t), s.orbit.r(t)),
              std::abs(0.5 * visors::core::kPi - sun_zenith), 1e-12);
}

// Finite differences every 0.1 s from 20 s before the slew to 20 s after the return slew: the
// rotation between samples never exceeds 1.5 deg/s (the default) x 0.1 s, to 1e-9 relative
// (round-off of the predicted states; the test orbit is circular so the prediction is exact).
TEST(AttitudeProfile, SlewRateNeverExceedsTheLimit) {
  const Scenario s;
  const double dt = 0.1, limit = 1.5 * kDegToRad * dt * (1.0 + 1e-9);
  double worst = 0.0;
  Eigen::Quaterniond previous = attitude(s.profile, s.orbit, s.window.slew_start_s - 20.0);
  for (double t = s.window.slew_start_s - 20.0 + dt; t < s.window.end_s + 200.0; t += dt) {
    const Eigen::Quaterniond q = attitude(s.profile, s.orbit, t);
    worst = std::max(worst, rotation_angle_rad(previous, q));
    previous = q;
  }
  EXPECT_LE(worst, limit);
}

// And the slew runs at the limit (eigen-axis slew at constant rate): 10 s into the slew the
// attitude has turned 15 deg from the slew-start attitude (1.5 deg/s x 10 s, hand).
TEST(AttitudeProfile, SlewRunsAtTheConfiguredRate) {
  const Scenario s;
  const double t0 = s.window.slew_start_s;
  // hand value (comment above); loose: measured 1.1e-16 rad (2026-11), bound 1e-9 rad ~1e7x above round-off
  EXPECT_NEAR(rotation_angle_rad(attitude(s.profile, s.orbit, t0), attitude(s.profile, s.orbit, t0 + 10.0)),
              15.0 * kDegToRad, 1e-9);
}

// Slew commanded with required_slew_lead_s: on the observation attitude (evaluated with the state
// at start_s) by start_s, to 1e-9 rad.
TEST(AttitudeProfile, ReachesObservationAttitudeByStartWithTheLeadTime) {
  const Scenario s;
  const double t = s.window.start_s;
  const Eigen::Quaterniond target =
      AttitudeProfile::observation_body_to_gcrf(s.orbit.r(t), s.orbit.v(t), s.orbit.sun);
  // once arrived the profile tracks the same target function (attitude_profile.cpp), so exact; loose: measured 0 (2026-11), bound 1e-9 rad ~5e6x above round-off (ulp(1 rad) 2.2e-16)
  EXPECT_LT(rotation_angle_rad(attitude(s.profile, s.orbit, t), target), 1e-9);
}

// ... and it arrives no later than start_s - settling (the settling time is the margin).
TEST(AttitudeProfile, ArrivesBeforeTheSettlingTime) {
  const Scenario s;
  const double t = s.window.start_s - 30.0 + 0.5;
  const Eigen::Quaterniond target =
      AttitudeProfile::observation_body_to_gcrf(s.orbit.r(t), s.orbit.v(t), s.orbit.sun);
  // tracking after arrival, exact (as above); loose: measured 0 (2026-11), bound 1e-9 rad ~5e6x above round-off
  EXPECT_LT(rotation_angle_rad(attitude(s.profile, s.orbit, t), target), 1e-9);
}

// Before the slew start the attitude is nominal (definition).
TEST(AttitudeProfile, NominalUntilTheSlewStarts) {
  const Scenario s;
  const double t = s.window.slew_start_s - 1.0;
  // definition (comment above); loose: measured 0 (2026-11), bound 1e-12 rad ~4500x above round-off (ulp(1 rad) 2.2e-16)
  EXPECT_LT(rotation_angle_rad(attitude(s.profile, s.orbit, t),
                               AttitudeProfile::nominal_body_to_gcrf(s.orbit.r(t), s.orbit.v(t), s.orbit.sun)),
            1e-12);
}

// After end_s + the lead time for the same angle it is back on nominal (slews back at the same
// rate; 1e-9 rad).
TEST(AttitudeProfile, ReturnsToNominalAfterTheWindow) {
  const Scenario s;
  const double t = s.window.end_s + s.profile.required_slew_lead_s(visors::core::kPi);
  // tracking the nominal target after the return slew, exact; loose: measured 0 (2026-11), bound 1e-9 rad ~5e6x above round-off
  EXPECT_LT(rotation_angle_rad(attitude(s.profile, s.orbit, t),
                               AttitudeProfile::nominal_body_to_gcrf(s.orbit.r(t), s.orbit.v(t), s.orbit.sun)),
            1e-9);
}

// Orthonormal rotation (R^T R = I, det R = 1 to 1e-12) at every phase: before, during both slews,
// the hold and after.
TEST(AttitudeProfile, RotationIsOrthonormal) {
  const Scenario s;
  double worst = 0.0;
  for (double t = s.window.slew_start_s - 50.0; t < s.window.end_s + 200.0; t += 3.7) {
    const Eigen::Matrix3d r = attitude(s.profile, s.orbit, t).toRotationMatrix();
    worst = std::max({worst, (r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), std::abs(r.determinant() - 1.0)});
  }
  // round-off of a normalised quaternion's matrix; loose: measured 6.7e-16 (2026-11), bound 1e-12 ~1500x above
  EXPECT_LT(worst, 1e-12);
}

// Degenerate nominal geometry: Sun on the zenith, +X falls back to the velocity direction
// (documented fallback).
TEST(AttitudeProfile, NominalFallsBackToVelocityWhenSunIsAtZenith) {
  const Eigen::Vector3d r(7e6, 0.0, 0.0), v(0.0, 5e3, 5e3);
  const Eigen::Quaterniond q = AttitudeProfile::nominal_body_to_gcrf(r, v, Eigen::Vector3d::UnitX());
  // documented fallback (comment above); loose: measured 0 (2026-11), bound 1e-12 rad ~4500x above round-off (ulp(1 rad) 2.2e-16)
  EXPECT_LT(angle_between(q * Eigen::Vector3d::UnitX(), v), 1e-12);
}

}  // namespace

// Calibration yaws (CalibrationYaw): 90 deg about the boresight from first_s = 3000 s, 120 s hold,
// once every 5700 s. At 1.5 deg/s each turn takes 60 s (hand), so the hold is [3060, 3180] s.
AttitudeProfile yawing_profile() {
  AttitudeSettings settings;
  settings.calibration = {.yaw_rad = 90.0 * kDegToRad, .hold_s = 120.0, .period_s = 5700.0, .first_s = 3000.0, .margin_s = 300.0};
  auto p = AttitudeProfile::create(settings);
  EXPECT_TRUE(p.ok());
  return std::move(p).value();
}

TEST(AttitudeProfile, CalibrationYawKeepsTheAntennaOnTheZenith) {
  const Orbit o;
  const AttitudeProfile p = yawing_profile();
  const double t = 3120.0;
  EXPECT_LT(visors::sim::antenna_off_zenith_rad(attitude(p, o, t), o.r(t)), 1e-9);
}

TEST(AttitudeProfile, CalibrationYawTurnsThePayloadAxisByTheYaw) {
  const Orbit o;
  const AttitudeProfile p = yawing_profile();
  const double t = 3120.0;
  const Eigen::Vector3d x_nominal = AttitudeProfile::nominal_body_to_gcrf(o.r(t), o.v(t), o.sun) * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(angle_between(attitude(p, o, t) * Eigen::Vector3d::UnitX(), x_nominal), 90.0 * kDegToRad, 1e-9);
}

// The sign: +90 deg about +Z takes body +X to where nominal +Y was (right-handed turn).
TEST(AttitudeProfile, CalibrationYawIsAPositiveTurnAboutBodyZ) {
  const Orbit o;
  const AttitudeProfile p = yawing_profile();
  const double t = 3120.0;
  const Eigen::Vector3d y_nominal = AttitudeProfile::nominal_body_to_gcrf(o.r(t), o.v(t), o.sun) * Eigen::Vector3d::UnitY();
  EXPECT_LT(angle_between(attitude(p, o, t) * Eigen::Vector3d::UnitX(), y_nominal), 1e-9);
}

TEST(AttitudeProfile, NominalBeforeTheFirstCalibrationYaw) {
  const Orbit o;
  const AttitudeProfile p = yawing_profile();
  const double t = 2999.0;
  EXPECT_LT(rotation_angle_rad(attitude(p, o, t), AttitudeProfile::nominal_body_to_gcrf(o.r(t), o.v(t), o.sun)), 1e-12);
}

TEST(AttitudeProfile, NominalAgainAfterTheCalibrationYaw) {
  const Orbit o;
  const AttitudeProfile p = yawing_profile();
  const double t = 3260.0;  // 3000 + 60 + 120 + 60 = 3240 s, the return done (hand)
  EXPECT_LT(rotation_angle_rad(attitude(p, o, t), AttitudeProfile::nominal_body_to_gcrf(o.r(t), o.v(t), o.sun)), 1e-9);
}

TEST(AttitudeProfile, CalibrationYawRepeatsAfterThePeriod) {
  const Orbit o;
  const AttitudeProfile p = yawing_profile();
  const double t = 3120.0 + 5700.0;
  const Eigen::Vector3d x_nominal = AttitudeProfile::nominal_body_to_gcrf(o.r(t), o.v(t), o.sun) * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(angle_between(attitude(p, o, t) * Eigen::Vector3d::UnitX(), x_nominal), 90.0 * kDegToRad, 1e-9);
}

TEST(AttitudeProfile, CalibrationYawTurnsNoFasterThanTheSlewRate) {
  const Orbit o;
  const AttitudeProfile p = yawing_profile();
  const double dt = 0.1, limit = 1.5 * kDegToRad * dt * (1.0 + 1e-9);
  double worst = 0.0;
  Eigen::Quaterniond previous = attitude(p, o, 2990.0);
  for (double t = 2990.0 + dt; t < 3300.0; t += dt) {
    const Eigen::Quaterniond q = attitude(p, o, t);
    worst = std::max(worst, rotation_angle_rad(previous, q));
    previous = q;
  }
  EXPECT_LE(worst, limit);
}

TEST(AttitudeProfile, CalibrationYawGivesWayToAnObservation) {
  const Orbit o;
  AttitudeProfile p = yawing_profile();
  ASSERT_TRUE(p.schedule({3400.0, 3500.0, 3600.0}).ok());  // within margin_s of the yaw's end
  EXPECT_FALSE(p.in_calibration_yaw(3120.0));
}

TEST(AttitudeProfile, CalibrationPeriodShorterThanAYawIsRejected) {
  AttitudeSettings settings;
  settings.calibration = {.yaw_rad = 90.0 * kDegToRad, .hold_s = 120.0, .period_s = 200.0};
  EXPECT_EQ(settings.validate().error().field, "calibration.period_s");
}
