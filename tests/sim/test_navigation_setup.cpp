// What the ground gives the on-board navigation (sim/navigation_setup.hpp): the flight team's
// settings, never the truth's (docs/truth-and-knowledge.md). Each test makes the truth differ
// and checks that the flight settings did not follow.
#include <gtest/gtest.h>

#include "sim/campaign_scenario.hpp"
#include "sim/navigation_setup.hpp"

namespace {

using visors::sim::default_campaign;

TEST(NavigationSetup, FilterPhaseWeightIgnoresTheTruthReceiverNoise) {
  auto s = default_campaign();
  s.gnss.receiver.phase_sigma_m = 0.05;
  EXPECT_EQ(visors::sim::cdgps_settings(s).value().sdcp_sigma_m, visors::nav::CdgpsSettings{}.sdcp_sigma_m);
}

TEST(NavigationSetup, FilterCodeWeightIgnoresTheTruthCodeMultipath) {
  auto s = default_campaign();
  s.gnss.receiver.code_multipath_m = 2.0;
  EXPECT_EQ(visors::sim::cdgps_settings(s).value().graphic_sigma_m, visors::nav::CdgpsSettings{}.graphic_sigma_m);
}

TEST(NavigationSetup, FilterWeightsFollowTheNavTable) {
  auto s = visors::sim::campaign_from_toml("[nav]\nsdcp_sigma_m = 0.004\n").value();
  EXPECT_EQ(visors::sim::cdgps_settings(s).value().sdcp_sigma_m, 0.004);
}

TEST(NavigationSetup, OnboardPhaseCentreOffsetIgnoresTheTruthAntenna) {
  auto s = default_campaign();
  s.gnss.receiver.phase_center_offset_m = 0.2;
  EXPECT_EQ(visors::sim::onboard_navigation_settings(s).value().antenna_pco_m,
            visors::gnc::OnboardNavigationSettings{}.antenna_pco_m);
}

TEST(NavigationSetup, OnboardRangefinderNoiseIgnoresTheTruthRangefinder) {
  auto s = default_campaign();
  s.gnss.lrf.sigma_m = 0.02;
  EXPECT_EQ(visors::sim::onboard_navigation_settings(s).value().lrf_sigma_m,
            visors::gnc::OnboardNavigationSettings{}.lrf_sigma_m);
}

TEST(NavigationSetup, PhaseCentrePriorIsTheFlightTeamsNotTheTruthsSigma) {
  auto s = default_campaign();
  s.geometry.phase_center_knowledge_sigma_m = 0.02;
  EXPECT_EQ(visors::sim::cdgps_settings(s).value().phase_center_sigma_m, 5e-3);
}

TEST(NavigationSetup, DefaultTruthReceiverHasTheRealSkysErrors) {
  // docs/truth-and-knowledge.md: elevation-dependent noise, 2 mm / 0.3 m zenith multipath, 60 s.
  const auto r = default_campaign().gnss.receiver;
  EXPECT_TRUE(r.elevation_dependent_noise);
  EXPECT_EQ(r.phase_multipath_m, 0.002);
  EXPECT_EQ(r.code_multipath_m, 0.3);
  EXPECT_EQ(r.multipath_tau_s, 60.0);
}

}  // namespace
