// Validation of the channel records: each bad field is rejected with its name.
#include <gtest/gtest.h>

#include <string_view>

#include <limits>

#include "visors/gnc/messages.hpp"
#include "visors/gnc/onboard_navigation.hpp"
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

// A crosslinked epoch whose satellite repeats: refused with the observations' field (the rule of
// nav::check for the filter's own epochs).
TEST(Messages, ARepeatedSatelliteInTheCrosslinkedEpochIsRejected) {
  CrosslinkMessage message;
  message.t = kNow;
  message.navigation.has_epoch = true;
  message.navigation.epoch.t = kNow;
  message.navigation.epoch.count = 2;
  message.navigation.epoch.observations[0].prn = 5;
  message.navigation.epoch.observations[1].prn = 5;
  const visors::core::Status check = validate(message, kNow);
  EXPECT_EQ(check.field(), std::string_view("crosslink.navigation.epoch.observations.prn"));
}

// The crosslink's epoch and the filter's are the same observations: a receiver epoch goes out
// and comes back bit for bit (gnc/onboard_navigation.hpp's conversions at the navigation's edge).
TEST(Messages, AReceiverEpochComesBackFromTheCrosslinkBitForBit) {
  visors::nav::GpsReceiverEpoch epoch;
  epoch.t = kNow;
  epoch.count = 3;
  epoch.observations[0] = {3, 2.2e7 + 0.1, 1.15e8 + 0.25, true, false};
  epoch.observations[1] = {17, 2.3e7 - 0.3, -1.2e8, false, true};
  epoch.observations[2] = {32, 2.4e7, 1.3e8 + 1e-6, true, true};
  const visors::nav::GpsReceiverEpoch back = receiver_epoch(crosslink_epoch(epoch));
  EXPECT_EQ(back.t, epoch.t);
  EXPECT_EQ(back.count, 3);
  for (std::size_t k = 0; k < 3; ++k) {
    const auto &a = back.observations[k], &b = epoch.observations[k];
    EXPECT_TRUE(a.prn == b.prn && a.code_m == b.code_m && a.phase_cycles == b.phase_cycles && a.loss_of_lock == b.loss_of_lock &&
                a.half_cycle == b.half_cycle)
        << k;
  }
}

TEST(Messages, PropulsionTelemetryNeedsPositiveMass) {
  const PropulsionTelemetry telemetry{kNow, Eigen::Vector3d::Zero(), -1.0, true};
  EXPECT_EQ(validate(telemetry, kNow).field(), std::string_view("propulsion.mass_kg"));
}

}  // namespace
