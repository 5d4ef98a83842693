// The campaign scenario: defaults from the test case of Guffanti et al., AAS 23-149, 2023,
// Table 5 (docs/requirements.md#mission-timeline-and-orbits), validation naming the key,
// and the resolved scenario read back.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "visors/core/constants.hpp"
#include "visors/sim/campaign_scenario.hpp"

namespace {

using visors::sim::campaign_from_toml;
using visors::sim::campaign_to_toml;
using visors::sim::default_campaign;
using visors::sim::NavigationMode;

std::string shipped_scenario() {
  std::ifstream in(std::string(VISORS_SOURCE_DIR) + "/data/scenarios/campaign.toml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Guffanti et al., AAS 23-149, 2023, Table 5: a = R_E + 500 km, e = 0.004, i = 97.8 deg,
// RAAN = 157.5 deg (R_E: the WGS-84 equatorial radius in the default, a project choice).
TEST(CampaignScenario, DefaultChiefIsTheMissionTestCase) {
  const auto s = default_campaign();
  // same expression as the default (campaign_scenario.cpp); loose: measured 0 (2026-11), bound 1e-6 m ~1000x above round-off (ulp(a) 9.3e-10 m)
  EXPECT_NEAR(s.chief_mean.a, visors::core::kWgs84SemiMajorAxis + 500e3, 1e-6);
  // same expressions as the default (campaign_scenario.cpp), round-off (ulp 2.2e-16 / 4.4e-16 rad); measured 0 (2026-11)
  EXPECT_NEAR(s.chief_mean.i, 97.8 * visors::core::kDegToRad, 1e-15);
  EXPECT_NEAR(s.chief_mean.raan, 157.5 * visors::core::kDegToRad, 1e-15);
}

// u(t0) = argp + M = 0 (the same Table 5).
TEST(CampaignScenario, DefaultArgumentOfLatitudeIsZero) {
  const auto s = default_campaign();
  // 90 deg - 90 deg cancels exactly (campaign_scenario.cpp), round-off (ulp(pi/2) 2.2e-16); measured 0 (2026-11)
  EXPECT_NEAR(std::remainder(s.chief_mean.argp + s.chief_mean.M, 2.0 * M_PI), 0.0, 1e-15);
}

// Guffanti et al., AAS 23-149, 2023, sec. 5: 45 min of standby; Table 5: 10 attempts, standby
// ROE a*dey = a*diy = 200 m.
TEST(CampaignScenario, DefaultTimelineAndStandbyOrbit) {
  const auto s = default_campaign();
  EXPECT_EQ(s.standby_s, 2700.0);
  EXPECT_EQ(s.observations, 10);
  EXPECT_EQ(s.initial_roe_m(3), 200.0);
  EXPECT_EQ(s.initial_roe_m(5), 200.0);
}

TEST(CampaignScenario, ShippedFileIsValid) { EXPECT_TRUE(campaign_from_toml(shipped_scenario()).ok()); }

TEST(CampaignScenario, ShippedFileKeepsTheDefaultMasses) {
  const auto s = campaign_from_toml(shipped_scenario()).value();
  EXPECT_EQ(s.dsc.mass_kg, 11.35);  // DSC 11.35 kg, OSC 10.62 kg: Guffanti et al., AAS 23-149, 2023, Table 4
  EXPECT_EQ(s.osc.mass_kg, 10.62);
}

TEST(CampaignScenario, UnknownKeyIsNamed) {
  const auto s = campaign_from_toml("[campaign]\nobservation = 3\n");
  EXPECT_EQ(s.error().field, "campaign.observation");
}

TEST(CampaignScenario, NegativeObservationsAreRejected) {
  const auto s = campaign_from_toml("[campaign]\nobservations = -1\n");
  EXPECT_EQ(s.error().field, "campaign.observations");
}

TEST(CampaignScenario, IntegrationStepMustDivideTheStep) {
  const auto s = campaign_from_toml("[time]\nstep_s = 1.0\nintegration_step_s = 0.3\n");
  EXPECT_EQ(s.error().field, "time.integration_step_s");
}

TEST(CampaignScenario, UnknownNavigationModeIsNamed) {
  const auto s = campaign_from_toml("[navigation]\nmode = \"gps\"\n");
  EXPECT_EQ(s.error().field, "navigation.mode");
}

// Carrier-phase GPS navigation is the campaign's default (the closed loop with the flight
// software's own navigation, as Guffanti et al., AAS 23-149, 2023, sec. 5, tests it); "ideal"
// stays for control-only studies; both read back from the resolved scenario.
TEST(CampaignScenario, NavigationIsCdgpsByDefault) {
  EXPECT_EQ(default_campaign().navigation_mode, NavigationMode::kCdgps);
}

TEST(CampaignScenario, NavigationModeReadsBack) {
  for (const char* mode : {"ideal", "cdgps"}) {
    const auto s = campaign_from_toml(std::string("[navigation]\nmode = \"") + mode + "\"\n").value();
    const auto back = campaign_from_toml(campaign_to_toml(s)).value();
    EXPECT_EQ(back.navigation_mode, s.navigation_mode) << mode;
  }
}

// The on-board filter's [nav] table: checked when the scenario is read (the key named), kept for
// the resolved scenario.
TEST(CampaignScenario, NavTunablesAreCheckedAndKept) {
  EXPECT_EQ(campaign_from_toml("[nav]\nsdcp_sigma_m = -1.0\n").error().field, "nav.sdcp_sigma_m");
  EXPECT_EQ(campaign_from_toml("[nav]\nno_such_key = 1.0\n").error().field, "nav.no_such_key");
  const auto s = campaign_from_toml("[nav]\ngate_sigmas = 4.5\n").value();
  EXPECT_NE(campaign_to_toml(s).find("gate_sigmas = 4.5"), std::string::npos);
}

TEST(CampaignScenario, GncThresholdOutOfRangeIsNamed) {
  const auto s = campaign_from_toml("[gnc]\nstandby_de_deadband_m = -1.0\n");
  EXPECT_NE(s.error().field.find("standby_keeping.de_deadband_m"), std::string::npos);
}

TEST(CampaignScenario, ForcesAreReadWithTheirOwnValidation) {
  const auto s = campaign_from_toml("[forces.gravity]\ndegree = -3\n");
  EXPECT_FALSE(s.ok());
}

// The fine-control burn times (gnc_config.hpp): six 150 s apart by default.
TEST(CampaignScenario, DefaultFineControlBurnsAreSix150SecondsApart) {
  const auto s = default_campaign();
  ASSERT_EQ(s.gnc.science.least_squares_burns, 6);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(s.gnc.science.least_squares_burns_before_s[static_cast<std::size_t>(k)], 900.0 - 150.0 * k);
}

TEST(CampaignScenario, FineControlBurnTimesAreRead) {
  const auto s = campaign_from_toml("[gnc]\nleast_squares_burns_before_s = [800.0, 400.0]\n").value();
  EXPECT_EQ(s.gnc.science.least_squares_burns, 2);
  EXPECT_EQ(s.gnc.science.least_squares_burns_before_s[1], 400.0);
}

TEST(CampaignScenario, TooManyFineControlBurnsAreNamed) {
  const auto s = campaign_from_toml("[gnc]\nleast_squares_burns_before_s = [800.0, 700.0, 600.0, 500.0, 400.0, 300.0, 200.0]\n");
  EXPECT_EQ(s.error().field, "gnc.least_squares_burns_before_s");
}

TEST(CampaignScenario, ANonNumericBurnTimeIsNamed) {
  const auto s = campaign_from_toml("[gnc]\nleast_squares_burns_before_s = [800.0, \"late\"]\n");
  EXPECT_EQ(s.error().field, "gnc.least_squares_burns_before_s");
}

// The order and the window are the GNC configuration's checks (gnc::validate).
TEST(CampaignScenario, IncreasingBurnTimesAreNamed) {
  const auto s = campaign_from_toml("[gnc]\nleast_squares_burns_before_s = [300.0, 600.0]\n");
  EXPECT_NE(s.error().field.find("science.least_squares_burns_before_s"), std::string::npos);
}

TEST(CampaignScenario, ABurnBeforeTheWindowIsNamed) {
  const auto s = campaign_from_toml("[gnc]\nleast_squares_window_s = 600.0\nleast_squares_burns_before_s = [900.0, 300.0]\n");
  EXPECT_NE(s.error().field.find("science.least_squares_burns_before_s"), std::string::npos);
}

TEST(CampaignScenario, ResolvedBurnTimesReadBack) {
  auto s = default_campaign();
  s.gnc.science.least_squares_burns = 3;
  s.gnc.science.least_squares_burns_before_s[2] = 123.25;
  const auto back = campaign_from_toml(campaign_to_toml(s)).value();
  EXPECT_EQ(back.gnc.science.least_squares_burns, 3);
  EXPECT_EQ(back.gnc.science.least_squares_burns_before_s[2], 123.25);
}

// The resolved scenario (the run directory's scenario.toml) reads back to the same values.
TEST(CampaignScenario, ResolvedScenarioReadsBack) {
  auto s = default_campaign();
  s.seed = 77;
  s.observations = 4;
  s.fault.impulse_t_s = 1234.5;
  s.gnc.safety.epsilon_m = 6.5;
  const auto back = campaign_from_toml(campaign_to_toml(s)).value();
  EXPECT_EQ(back.seed, 77U);
  EXPECT_EQ(back.observations, 4);
  EXPECT_EQ(back.fault.impulse_t_s, 1234.5);
  EXPECT_EQ(back.gnc.safety.epsilon_m, 6.5);
  EXPECT_EQ(back.chief_mean.a, s.chief_mean.a);
}

TEST(CampaignScenario, GeometryKeysAreRead) {
  const auto s = campaign_from_toml("[geometry]\ncom_knowledge_error_m = 0.01\ncom_variation_sigma_m = 0.002\n").value();
  EXPECT_EQ(s.geometry.com_knowledge_error_m, 0.01);
  EXPECT_EQ(s.geometry.com_sigma_m, 0.002);
}

TEST(CampaignScenario, GeometryDefaultsAreThePapers) {
  const auto s = campaign_from_toml("").value();  // 3 mm CoM variation, 30 arcsec boresight: Guffanti et al., AAS 23-149, 2023, Table 1(a)
  EXPECT_EQ(s.geometry.com_sigma_m, 3e-3);
  EXPECT_NEAR(s.geometry.payload_pointing_sigma_rad / 4.84813681109536e-6, 30.0, 1e-12);
}

TEST(CampaignScenario, NegativeKnowledgeErrorIsNamed) {
  EXPECT_EQ(campaign_from_toml("[geometry]\ncom_knowledge_error_m = -0.01\n").error().field, "geometry.com_knowledge_error_m");
}

TEST(CampaignScenario, UnknownGeometryKeyIsNamed) {
  EXPECT_EQ(campaign_from_toml("[geometry]\ncom_error = 0.01\n").error().field, "geometry.com_error");
}

TEST(CampaignScenario, ResolvedGeometryReadsBack) {
  auto s = default_campaign();
  s.geometry.com_knowledge_error_m = 0.0125;
  s.geometry.payload_pointing_sigma_rad = 1e-5;
  const auto back = campaign_from_toml(campaign_to_toml(s)).value();
  EXPECT_EQ(back.geometry.com_knowledge_error_m, 0.0125);
  EXPECT_NEAR(back.geometry.payload_pointing_sigma_rad, 1e-5, 1e-20);
}

TEST(CampaignScenario, PhaseCentreKnowledgeDefaultIsFiveMillimetres) {
  // docs/truth-and-knowledge.md: larger than the paper's 3 mm centre-of-mass variation.
  EXPECT_EQ(campaign_from_toml("").value().geometry.phase_center_knowledge_sigma_m, 5e-3);
}

TEST(CampaignScenario, PhaseCentreKnowledgeIsRead) {
  const auto s = campaign_from_toml("[geometry]\nphase_center_knowledge_sigma_m = 0.01\n").value();
  EXPECT_EQ(s.geometry.phase_center_knowledge_sigma_m, 0.01);
}

TEST(CampaignScenario, NegativePhaseCentreKnowledgeIsNamed) {
  EXPECT_EQ(campaign_from_toml("[geometry]\nphase_center_knowledge_sigma_m = -0.01\n").error().field,
            "geometry.phase_center_knowledge_sigma_m");
}

TEST(CampaignScenario, ResolvedPhaseCentreKnowledgeReadsBack) {
  auto s = default_campaign();
  s.geometry.phase_center_knowledge_sigma_m = 0.0075;
  EXPECT_EQ(campaign_from_toml(campaign_to_toml(s)).value().geometry.phase_center_knowledge_sigma_m, 0.0075);
}

TEST(CampaignScenario, TargetOffsetIsGivenToTheFlightSoftware) {
  // A ground command: the flight components aim at what the truth scores against.
  const auto s = campaign_from_toml("[campaign]\ntarget_offset_arcsec = [100.0, -50.0]\n").value();
  EXPECT_NEAR(s.gnc.science.geometry.target_offset_rad.x(), 100.0 * visors::core::kArcsecToRad, 1e-18);
  EXPECT_NEAR(s.gnc.science.geometry.target_offset_rad.y(), -50.0 * visors::core::kArcsecToRad, 1e-18);
}

TEST(CampaignScenario, TargetOffsetIsTheTruthsToo) {
  const auto s = campaign_from_toml("[campaign]\ntarget_offset_arcsec = [100.0, -50.0]\n").value();
  EXPECT_EQ(s.target_offset_rad, s.gnc.science.geometry.target_offset_rad);
}

TEST(CampaignScenario, DefaultTargetIsOffTheDiscCentre) {
  // docs/apparent-sun.md: an active region 310" east, 240" south, in the default and shipped file.
  const auto s = campaign_from_toml("").value();
  EXPECT_NEAR(s.target_offset_rad.x() / visors::core::kArcsecToRad, 310.0, 1e-9);
  EXPECT_NEAR(campaign_from_toml(shipped_scenario()).value().target_offset_rad.y() / visors::core::kArcsecToRad, -240.0, 1e-9);
}

TEST(CampaignScenario, TargetBeyondTheCoronaIsNamed) {
  EXPECT_EQ(campaign_from_toml("[campaign]\ntarget_offset_arcsec = [1000.0, 1000.0]\n").error().field,
            "campaign.target_offset_arcsec");
}

TEST(CampaignScenario, TargetOffsetOfThreeNumbersIsNamed) {
  EXPECT_EQ(campaign_from_toml("[campaign]\ntarget_offset_arcsec = [1.0, 2.0, 3.0]\n").error().field,
            "campaign.target_offset_arcsec");
}

TEST(CampaignScenario, ResolvedTargetOffsetReadsBack) {
  auto s = default_campaign();
  s.target_offset_rad = Eigen::Vector2d(-123.25, 456.5) * visors::core::kArcsecToRad;
  const auto back = campaign_from_toml(campaign_to_toml(s)).value();
  EXPECT_NEAR(back.target_offset_rad.x(), s.target_offset_rad.x(), 1e-18);
  EXPECT_NEAR(back.gnc.science.geometry.target_offset_rad.y(), s.target_offset_rad.y(), 1e-18);
}

TEST(CampaignScenario, NozzleBiasSigmaIsOffByDefault) {
  EXPECT_EQ(campaign_from_toml("").value().propulsion.magnitude_bias_sigma, 0.0);
}

TEST(CampaignScenario, ResolvedNozzleBiasSigmaReadsBack) {
  auto s = campaign_from_toml("[propulsion]\nmagnitude_bias_sigma = 0.02\n").value();
  EXPECT_EQ(campaign_from_toml(campaign_to_toml(s)).value().propulsion.magnitude_bias_sigma, 0.02);
}

TEST(CampaignScenario, NozzleBiasSigmaOutOfRangeIsNamed) {
  EXPECT_EQ(campaign_from_toml("[propulsion]\nmagnitude_bias_sigma = 0.7\n").error().field, "propulsion.magnitude_bias_sigma");
}

TEST(CampaignScenario, ResolvedForcesTableReadsBack) {
  const auto s = campaign_from_toml("[forces]\npreset = \"onboard\"\n[forces.gravity]\ndegree = 8\norder = 8\n").value();
  const auto back = campaign_from_toml(campaign_to_toml(s)).value();
  EXPECT_EQ(back.forces.gravity.degree, 8);
}

// [forces.drag] chooses NRLMSISE-00 (config/force_model_toml.hpp), the truth preset's default.
TEST(CampaignScenario, DragAtmosphereNrlmsise00IsRead) {
  EXPECT_EQ(default_campaign().forces.drag.atmosphere, visors::dynamics::AtmosphereKind::kNrlmsise00);
  const auto s = campaign_from_toml(
                     "[forces]\npreset = \"onboard\"\n[forces.drag]\natmosphere = \"nrlmsise00\"\nap_history = false\n")
                     .value();
  EXPECT_EQ(s.forces.drag.atmosphere, visors::dynamics::AtmosphereKind::kNrlmsise00);
  EXPECT_FALSE(s.forces.drag.ap_history);
  const auto back = campaign_from_toml(campaign_to_toml(s)).value();
  EXPECT_EQ(back.forces.drag.atmosphere, visors::dynamics::AtmosphereKind::kNrlmsise00);
}

TEST(CampaignScenario, UnknownDragAtmosphereIsNamed) {
  const auto s = campaign_from_toml("[forces.drag]\natmosphere = \"jacchia\"\n");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().field.find("forces.drag.atmosphere"), std::string::npos) << s.error().field;
  EXPECT_NE(s.error().message.find("\"nrlmsise00\""), std::string::npos) << s.error().message;
}

}  // namespace

