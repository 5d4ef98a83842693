// Validation of the channel records: each bad field is rejected with its name.
#include <gtest/gtest.h>

#include <string_view>

#include <limits>

#include "visors/gnc/messages.hpp"
#include "formation_harness.hpp"

namespace {

using namespace visors::gnc;
using visors::core::GpsTime;

const GpsTime kNow = GpsTime::from_seconds(1.4e9);

NavigationSolution good_navigation() {
  test::FormationHarness h(test::mission_chief(), test::roe_m(0, 0, 0, 200, 0, 200), kNow);
  return h.navigation(0.0);
}

TEST(Messages, GoodNavigationIsAccepted) { EXPECT_TRUE(validate(good_navigation(), kNow).ok()); }

TEST(Messages, NanPositionIsRejectedByName) {
  auto nav = good_navigation();
  nav.deputy_gcrf.r.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validate(nav, kNow).field(), std::string_view("navigation.deputy_gcrf"));
}

TEST(Messages, FutureTimeTagIsRejected) {
  auto nav = good_navigation();
  nav.t = kNow + 1.0;
  EXPECT_EQ(validate(nav, kNow).field(), std::string_view("navigation.t"));
}

TEST(Messages, StaleNavigationIsRejected) {
  EXPECT_EQ(validate(good_navigation(), kNow + 6.0).field(), std::string_view("navigation.t"));
}

TEST(Messages, AsymmetricCovarianceIsRejected) {
  auto nav = good_navigation();
  nav.relative_covariance_rtn(0, 1) = 1e-3;
  EXPECT_EQ(validate(nav, kNow).field(), std::string_view("navigation.relative_covariance_rtn"));
}

TEST(Messages, NonUnitQuaternionIsRejected) {
  const TimeAtTone tone{kNow, Eigen::Quaterniond(2.0, 0.0, 0.0, 0.0)};
  EXPECT_EQ(validate(tone, kNow).field(), std::string_view("time_at_tone.q_body_to_gcrf"));
}

TEST(Messages, ScienceCommandNeedsObservations) {
  const GroundCommand command{kNow, GroundCommand::Kind::kStartScience, 0};
  EXPECT_EQ(validate(command, kNow).field(), std::string_view("command.observations"));
}

TEST(Messages, UnknownModeInCrosslinkIsRejected) {
  CrosslinkMessage message;
  message.t = kNow;
  message.mode = static_cast<Mode>(17);
  EXPECT_EQ(validate(message, kNow).field(), std::string_view("crosslink.mode"));
}

TEST(Messages, PropulsionTelemetryNeedsPositiveMass) {
  const PropulsionTelemetry telemetry{kNow, Eigen::Vector3d::Zero(), -1.0, true};
  EXPECT_EQ(validate(telemetry, kNow).field(), std::string_view("propulsion.mass_kg"));
}

}  // namespace
