// mc/campaign_file: the campaign TOML, its checks against the base scenario, errors naming the
// field.
#include "visors/mc/campaign_file.hpp"

#include <gtest/gtest.h>

#include "mc_test_campaign.hpp"

namespace visors::mc {
namespace {

core::Result<Campaign> parse(const std::string& text) {
  return campaign_from_toml(text, {}, std::string(test::kBaseScenario));
}

TEST(CampaignFile, TinyCampaignReads) { EXPECT_TRUE(parse(test::kTinyCampaign).ok()); }

TEST(CampaignFile, RunsAreValuesTimesRunsPerValue) { EXPECT_EQ(parse(test::kTinyCampaign)->total_runs(), 4); }

TEST(CampaignFile, WithoutSweepsRunsIsTheCount) { EXPECT_EQ(parse("runs = 5\n")->total_runs(), 5); }

TEST(CampaignFile, UnknownTopLevelKeyIsNamed) { EXPECT_EQ(parse("run = 5\n").error().field, "run"); }

TEST(CampaignFile, UnknownScenarioKeyInASweepIsNamed) {
  const auto c = parse("[[sweep]]\nkey = \"propulsion.isp\"\nvalues = [40.0]\n");
  EXPECT_EQ(c.error().field, "sweep[0].values");
}

TEST(CampaignFile, TheScenarioReadersComplaintIsKept) {
  const auto c = parse("[[sweep]]\nkey = \"propulsion.isp\"\nvalues = [40.0]\n");
  EXPECT_NE(c.error().message.find("propulsion.isp: is not a recognised key"), std::string::npos);
}

TEST(CampaignFile, AFloatForAnIntegerKeyIsRefused) {
  EXPECT_EQ(parse("[[sweep]]\nkey = \"campaign.observations\"\nvalues = [2.5]\n").error().field, "sweep[0].values");
}

// Arrays of numbers are values too: a burn schedule can be set or swept.
TEST(CampaignFile, AnArrayOfNumbersCanBeSwept) {
  const auto c = parse("[[sweep]]\nkey = \"gnc.least_squares_burns_before_s\"\nvalues = [[900.0, 540.0, 180.0], [600, 300]]\n");
  ASSERT_TRUE(c.ok()) << c.error().describe();
  EXPECT_EQ(to_text(c->sweeps[0].values[1]), "[600.0, 300.0]");
}

// An increasing schedule: the scenario reader's complaint names the key.
TEST(CampaignFile, AnArrayTheScenarioRefusesIsNamed) {
  const auto c = parse("[set]\n\"gnc.least_squares_burns_before_s\" = [300.0, 600.0]\n");
  EXPECT_NE(c.error().message.find("science.least_squares_burns_before_s"), std::string::npos) << c.error().describe();
}

TEST(CampaignFile, ANestedArrayIsNamedWithItsElement) {
  const auto c = parse("[set]\n\"formation.initial_roe_m\" = [0.0, [1.0]]\n");
  EXPECT_EQ(c.error().field, "set.\"formation.initial_roe_m\"[1]");
}

TEST(CampaignFile, AnEmptyArrayIsRefused) {
  EXPECT_EQ(parse("[set]\n\"formation.initial_roe_m\" = []\n").error().field, "set.\"formation.initial_roe_m\"");
}

TEST(CampaignFile, ADispersionBeyondTheKeysRangeAtThreeSigmaIsRefused) {
  // isp_sigma_s must be >= 0: mean 0.5, sigma 1 reaches -2.5 at 3 sigma.
  const auto c = parse("[dispersions]\n\"propulsion.isp_sigma_s\" = { normal = { mean = 0.5, sigma = 1.0 } }\n");
  EXPECT_EQ(c.error().field, "dispersions.\"propulsion.isp_sigma_s\"");
}

TEST(CampaignFile, UnknownDistributionIsNamed) {
  const auto c = parse("[dispersions]\n\"propulsion.isp_s\" = { gamma = { k = 1.0 } }\n");
  EXPECT_EQ(c.error().field, "dispersions.\"propulsion.isp_s\"");
}

TEST(CampaignFile, NegativeSigmaIsNamed) {
  const auto c = parse("[dispersions]\n\"propulsion.isp_s\" = { normal = { mean = 44.0, sigma = -1.0 } }\n");
  EXPECT_EQ(c.error().field, "dispersions.\"propulsion.isp_s\".normal.sigma");
}

TEST(CampaignFile, UniformWithMaxBelowMinIsNamed) {
  const auto c = parse("[dispersions]\n\"propulsion.isp_s\" = { uniform = { min = 44.0, max = 40.0 } }\n");
  EXPECT_EQ(c.error().field, "dispersions.\"propulsion.isp_s\".uniform.max");
}

TEST(CampaignFile, BadChoiceIsNamed) {
  const auto c = parse("[dispersions]\n\"navigation.mode\" = { choice = [\"ideal\", \"perfect\"] }\n");
  EXPECT_EQ(c.error().field, "dispersions.\"navigation.mode\"");
}

TEST(CampaignFile, SettingTheSeedIsRefused) { EXPECT_EQ(parse("[set]\nseed = 3\n").error().field, "set.\"seed\""); }

TEST(CampaignFile, RunsWithSweepsIsRefused) {
  EXPECT_EQ(parse("runs = 3\n[[sweep]]\nkey = \"crosslink.delay_s\"\nvalues = [0.5]\n").error().field, "runs");
}

TEST(CampaignFile, EmptySweepValuesAreRefused) {
  EXPECT_EQ(parse("[[sweep]]\nkey = \"crosslink.delay_s\"\nvalues = []\n").error().field, "sweep[0].values");
}

TEST(CampaignFile, MissingBaseScenarioIsNamed) {
  EXPECT_EQ(campaign_from_toml("scenario = \"nowhere/absent.toml\"\n", "/nonexistent").error().field, "scenario");
}

TEST(CampaignFile, BaseScenarioIsFoundBesideTheCampaign) {
  const auto dir = test::campaign_folder("beside");
  const auto c = load_campaign((dir / "campaign.toml").string());
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(c.ok()) << c.error().describe();
  EXPECT_EQ(c->scenario_path.filename(), "base.toml");
}

TEST(CampaignFile, ShippedSensitivityCampaignIsValid) {
  const auto c = load_campaign("campaigns/paper_sensitivity.toml");
  ASSERT_TRUE(c.ok()) << c.error().describe();
  EXPECT_EQ(c->sweeps.size(), 4U);  // CoM knowledge, magnitude error, direction error (the paper's figure), phase centre
}

TEST(CampaignFile, ShippedIdealNavigationCentreOfMassCampaignIsValid) {
  const auto c = load_campaign("campaigns/com_knowledge_ideal_navigation.toml");
  ASSERT_TRUE(c.ok()) << c.error().describe();
  EXPECT_EQ(c->total_runs(), 50);  // 5 values x 10 runs: 100 attempts per value
}

TEST(CampaignFile, ShippedFineControlScheduleCampaignIsValid) {
  const auto c = load_campaign("campaigns/fine_control_schedules.toml");
  ASSERT_TRUE(c.ok()) << c.error().describe();
  EXPECT_EQ(c->total_runs(), 18);  // 3 schedules x 6 runs
}

}  // namespace
}  // namespace visors::mc
