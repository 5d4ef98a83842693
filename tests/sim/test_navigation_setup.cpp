// What the ground gives the on-board navigation (sim/navigation_setup.hpp): the flight team's
// settings, never the truth's (docs/truth-and-knowledge.md). Each test makes the truth differ
// and checks that the flight settings did not follow.
#include <gtest/gtest.h>

#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/navigation_setup.hpp"

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

namespace {

// Ballistic knowledge: the flight software's [flight] values against the truth's [dsc]/[osc].
TEST(FlightKnowledge, TruthMassDoesNotReachTheFlightSoftware) {
  const auto s = visors::sim::campaign_from_toml("[dsc]\nmass_kg = 12.0\n").value();
  EXPECT_EQ(s.flight.dsc_mass_kg, 11.35);
}

TEST(FlightKnowledge, OnboardForceModelHasTheToldMass) {
  auto s = default_campaign();
  s.flight.osc_mass_kg = 10.0;
  s.osc.mass_kg = 11.0;
  EXPECT_EQ(visors::sim::onboard_force_model(s.flight, visors::gnc::Spacecraft::kOsc).value().spacecraft().mass, 10.0);
}

TEST(FlightKnowledge, FlightTableIsRead) {
  const auto s = visors::sim::campaign_from_toml("[flight]\ncd = 2.4\nosc_mass_kg = 10.5\n").value();
  EXPECT_EQ(s.flight.cd, 2.4);
}

TEST(FlightKnowledge, FlightValueOutOfRangeIsNamed) {
  EXPECT_EQ(visors::sim::campaign_from_toml("[flight]\ncr = 3.0\n").error().field, "flight.cr");
}

TEST(FlightKnowledge, UnknownFlightKeyIsNamed) {
  EXPECT_EQ(visors::sim::campaign_from_toml("[flight]\nmass_kg = 3.0\n").error().field, "flight.mass_kg");
}

TEST(FlightKnowledge, ResolvedFlightTableReadsBack) {
  auto s = default_campaign();
  s.flight.drag_area_m2 = 0.41;
  EXPECT_EQ(visors::sim::campaign_from_toml(visors::sim::campaign_to_toml(s)).value().flight.drag_area_m2, 0.41);
}

TEST(FlightKnowledge, ResolvedTruthSigmasReadBack) {
  auto s = default_campaign();
  s.dsc.cd_sigma = 0.125;
  EXPECT_EQ(visors::sim::campaign_from_toml(visors::sim::campaign_to_toml(s)).value().dsc.cd_sigma, 0.125);
}

TEST(FlightKnowledge, TooLargeTruthSigmaIsNamed) {
  EXPECT_EQ(visors::sim::campaign_from_toml("[osc]\ncd_sigma = 1.0\n").error().field, "osc.cd_sigma");
}

}  // namespace
