// flight_config.json (sim/flight_config.hpp): the flight components' configuration as created,
// untouched by any truth key: dispersing one leaves it byte-identical (docs/truth-and-knowledge.md).
#include <gtest/gtest.h>

#include <string>

#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/flight_config.hpp"

namespace {

using visors::sim::campaign_from_toml;
using visors::sim::flight_config_json;

std::string config_of(const std::string& toml) {
  const auto scenario = campaign_from_toml(toml);
  EXPECT_TRUE(scenario.ok()) << toml << ": " << (scenario.ok() ? "" : scenario.error().describe());
  if (!scenario.ok()) return "";
  const auto config = flight_config_json(scenario.value());
  EXPECT_TRUE(config.ok()) << toml << ": " << (config.ok() ? "" : config.error().describe());
  return config.ok() ? config.value().dump() : "";
}

// Every truth key of the scenario (docs/cli/run.md "Scenario keys", truth tables), each moved from its
// default; the flight configuration is compared as text.
class TruthKeyDispersion : public ::testing::TestWithParam<const char*> {};

TEST_P(TruthKeyDispersion, LeavesTheFlightConfigurationByteIdentical) {
  EXPECT_EQ(config_of(GetParam()), config_of(""));
}

INSTANTIATE_TEST_SUITE_P(
    TruthKeys, TruthKeyDispersion,
    ::testing::Values("seed = 7\n", "[dsc]\nmass_kg = 11.8\n", "[dsc]\ncd = 2.4\n", "[dsc]\ncr = 1.5\n",
                      "[dsc]\nsrp_area_m2 = 0.4\n", "[dsc]\nmass_sigma_kg = 0.1\n", "[osc]\nmass_kg = 10.0\n",
                      "[osc]\ncd_sigma = 0.1\n", "[osc]\npropellant_kg = 0.1\n",
                      "[geometry]\ncom_variation_sigma_m = 0.005\n", "[geometry]\ncom_knowledge_error_m = 0.01\n",
                      "[geometry]\npayload_position_sigma_m = 0.001\n", "[geometry]\npayload_pointing_sigma_arcsec = 60\n",
                      "[geometry]\nphase_center_knowledge_sigma_m = 0.02\n",
                      "[gnss.receiver]\nphase_sigma_m = 0.005\n", "[gnss.receiver]\ncode_sigma_m = 0.5\n",
                      "[gnss.receiver]\nphase_multipath_m = 0.004\n", "[gnss.receiver]\ncode_multipath_m = 0.6\n",
                      "[gnss.receiver]\nelevation_dependent_noise = false\n", "[gnss.receiver]\nphase_center_offset_m = 0.09\n",
                      "[gnss.receiver]\nantenna_body_m = [0.0, 0.01, 0.1]\n", "[gnss.lrf]\nsigma_m = 0.004\n", "[gnss.lrf]\nbias_m = 0.001\n",
                      "[propulsion]\nmagnitude_sigma = 0.2\n", "[propulsion]\nmagnitude_bias_sigma = 0.05\n",
                      "[propulsion]\ndirection_sigma_deg = 1.0\n", "[propulsion]\nisp_s = 40.0\n",
                      "[attitude]\nslew_rate_deg_s = 1.0\n", "[attitude]\npointing_sigma_arcsec = [10.0, 10.0, 10.0]\n",
                      "[attitude]\npointing_tau_s = 10.0\n", "[attitude]\njitter_sigma_arcsec = [1.0, 2.0, 3.0]\n",
                      "[attitude]\nknowledge_sigma_arcsec = [20.0, 20.0, 20.0]\n", "[attitude]\nknowledge_tau_s = 5.0\n",
                      "[clock]\npps_sigma_ns = 100\n", "[clock]\noscillator_sigma_ppm = 50\n",
                      "[crosslink]\ndelay_s = 1.0\n", "[crosslink]\ndrop_probability = 0.1\n",
                      "[forces]\npreset = \"onboard\"\n"));

// The check can tell a change: a flight key moves the file.
TEST(FlightConfig, AFlightKeyChangesIt) { EXPECT_NE(config_of("[flight]\ncd = 2.4\n"), config_of("")); }

// The antenna and rangefinder the flight software is told are flight keys of their own.
TEST(FlightConfig, TheAntennaKeyChangesIt) { EXPECT_NE(config_of("[flight]\nantenna_pco_m = 0.09\n"), config_of("")); }

TEST(FlightConfig, TheRangefinderKeyChangesIt) { EXPECT_NE(config_of("[flight]\nlrf_sigma_m = 0.003\n"), config_of("")); }

TEST(FlightConfig, AFilterKeyChangesIt) { EXPECT_NE(config_of("[nav]\nsdcp_sigma_m = 0.004\n"), config_of("")); }

TEST(FlightConfig, EachComponentHasItsOwnSelfAndRole) {
  const auto j = nlohmann::json::parse(config_of(""));
  EXPECT_EQ(j["osc"]["gnc"]["self"], "osc");
  EXPECT_EQ(j["osc"]["gnc"]["active"], true);
  EXPECT_EQ(j["dsc"]["gnc"]["active"], false);
}

TEST(FlightConfig, FilterIsTheOwnSpacecrafts) {
  EXPECT_EQ(nlohmann::json::parse(config_of(""))["dsc"]["navigation"]["filter"]["local"], "dsc");
}

TEST(FlightConfig, OnboardMassIsTheToldOne) {
  EXPECT_EQ(nlohmann::json::parse(config_of("[flight]\nosc_mass_kg = 10.5\n"))["dsc"]["force_models"]["osc"]["mass"], 10.5);
}

}  // namespace
