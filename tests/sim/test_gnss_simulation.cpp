// Shortened `visors gnss-sim` runs (the one-orbit default is a README command) and the [gnss]
// scenario tables.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <vector>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/files/data_path.hpp"
#include "gnss/files/rinex_nav_file.hpp"
#include "gnss/files/rinex_obs_file.hpp"
#include "gnss/gps_constants.hpp"
#include "sim/campaign_scenario.hpp"
#include "sim/gnss_simulation.hpp"

namespace {

using visors::sim::campaign_from_toml;
using visors::sim::campaign_to_toml;
using visors::sim::run_gnss_simulation;

constexpr const char* kNavFile = "gnss/NYA100NOR_S_20241280000_01D_GN.rnx";  // the [gnss] default

std::filesystem::path out_dir(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("visors_gnss_" + std::to_string(::getpid()) + "_" + name);
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

// The science formation for `duration` seconds (the default gnss_sim.toml's geometry).
std::string scenario(double duration, const std::string& extra = "") {
  return "name = \"gnss_test\"\n[formation]\ninitial_roe_m = [0.015, 35.09, -34.77, 5.10, -19.09, 2.81]\n[gnss]\nduration_s = " +
         std::to_string(duration) + "\n" + extra;
}

class GnssSimulation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(out_dir("run"));
    if (!visors::core::files::find_data_file(kNavFile)) return;
    const auto result = run_gnss_simulation(campaign_from_toml(scenario(120.0)).value(), *dir_);
    ASSERT_TRUE(result.ok()) << result.error().describe();
    summary_ = new nlohmann::json(result->summary);
  }
  void SetUp() override {
    if (summary_ == nullptr) GTEST_SKIP() << kNavFile << " not found: set VISORS_DATA_PATH to the shared data folder";
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete dir_;
    delete summary_;
  }
  static inline std::filesystem::path* dir_ = nullptr;
  static inline nlohmann::json* summary_ = nullptr;
};

TEST_F(GnssSimulation, SummaryCountsEpochsAndSatellites) {
  EXPECT_EQ((*summary_)["epochs"].get<int>(), 121);
  EXPECT_EQ((*summary_)["satellites"].get<int>(), 31);  // the NYA1 file's G02-G32
  for (const char* name : {"dsc", "osc"}) {
    const double tracked = (*summary_)["receivers"][name]["mean_tracked"].get<double>();
    // lower bound 6 chosen; upper bound: the 12 channels (gps_receiver.hpp default); measured 12.0 for dsc and osc (2026-11)
    EXPECT_GE(tracked, 6.0) << name;
    EXPECT_LE(tracked, 12.0) << name;
  }
}

TEST_F(GnssSimulation, TruthFilesHaveOneRowPerEpochAndSpacecraft) {
  EXPECT_EQ(lines(read(*dir_ / "truth.csv")), 1u + 2u * 121u);
  const std::string channels = read(*dir_ / "channels_truth.csv");
  // at least 6 tracked per epoch and spacecraft (bound above); measured 2905 lines = 1 + 2 x 121 x 12 (2026-11)
  EXPECT_GT(lines(channels), 2u * 121u * 6u);
}

// The broadcast file is re-read by the project's reader: one record per satellite, and the
// ionosphere of the source file's header (NYA1 GPSA alpha0 = 2.5146E-08).
TEST_F(GnssSimulation, BroadcastNavigationFileIsReadable) {
  const auto nav = visors::gnss::files::read_rinex_navigation(*dir_ / "brdc.rnx");
  ASSERT_TRUE(nav.ok()) << nav.error().describe();
  EXPECT_EQ(nav->records.size(), 31u);
  ASSERT_TRUE(nav->ionosphere.has_value());
  EXPECT_DOUBLE_EQ(nav->ionosphere->alpha[0], 2.5146e-08);
  EXPECT_EQ(nav->leap_seconds, 18);
}

TEST_F(GnssSimulation, ResolvedScenarioIsReadBack) {
  const auto again = campaign_from_toml(read(*dir_ / "scenario.toml"));
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_DOUBLE_EQ(again->gnss.duration_s, 120.0);
  // Every [gnss] value survives the round trip (the [forces] table is re-printed by toml++).
  EXPECT_NE(read(*dir_ / "scenario.toml").find(visors::sim::gnss_settings_to_toml(again->gnss)), std::string::npos);
}

TEST(GnssScenario, UnknownReceiverKeyIsNamed) {
  const auto s = campaign_from_toml(scenario(10.0, "[gnss.receiver]\nmask_deg = 10\n"));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().field, "gnss.receiver.mask_deg");
}

TEST(GnssScenario, BadValuesAreNamed) {
  EXPECT_EQ(campaign_from_toml(scenario(10.0, "[gnss.receiver]\nchannels = 20\n")).error().field, "gnss.receiver.channels");
  EXPECT_EQ(campaign_from_toml(scenario(10.0, "[gnss.receiver]\ncode_sigma_m = -0.2\n")).error().field,
            "gnss.receiver.code_sigma_m");
  EXPECT_EQ(campaign_from_toml(scenario(10.0, "[gnss.broadcast_errors]\nalong_m = -1\n")).error().field,
            "gnss.broadcast_errors.along_m");
  EXPECT_EQ(campaign_from_toml(scenario(10.0, "attitude = \"sideways\"\n")).error().field, "gnss.attitude");
  EXPECT_EQ(campaign_from_toml(scenario(10.0, "source_time_gps = \"yesterday\"\n")).error().field, "gnss.source_time_gps");
}

TEST(GnssScenario, MissingNavigationFileIsNamed) {
  const auto s = campaign_from_toml(scenario(10.0, "nav_file = \"gnss/none.rnx\"\n")).value();
  const auto dir = out_dir("missing");
  const auto result = run_gnss_simulation(s, dir);
  std::filesystem::remove_all(dir);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().field, "gnss.nav_file");
}

// Same seed, same measurements (deterministic random streams per model).
TEST(GnssScenario, SameSeedSameTruth) {
  if (!visors::core::files::find_data_file(kNavFile)) GTEST_SKIP() << kNavFile << " not found: set VISORS_DATA_PATH";
  const auto s = campaign_from_toml(scenario(20.0, "rinex = false\n")).value();
  const auto a = out_dir("a"), b = out_dir("b");
  ASSERT_TRUE(run_gnss_simulation(s, a).ok());
  ASSERT_TRUE(run_gnss_simulation(s, b).ok());
  EXPECT_EQ(read(a / "channels_truth.csv"), read(b / "channels_truth.csv"));
  EXPECT_FALSE(std::filesystem::exists(a / "brdc.rnx"));
  std::filesystem::remove_all(a);
  std::filesystem::remove_all(b);
}

}  // namespace

namespace {

// The acceptance: the RINEX output re-read by the reader gives the same observations.
// Checked against the truth file: every C1C is range + receiver clock - satellite clock +
// ionosphere within 5 sigma of the 0.20 m code noise, every L1C (x lambda) the same with the
// ionosphere's sign reversed plus lambda (N + phi_r - phi^j), within 5 sigma of the 2 mm phase
// noise plus the format's 0.0005-cycle rounding; one RINEX observation per truth channel row. (The
// receiver clock, which a real receiver does not know, is in truth.csv, 0.1 mm resolution.)
TEST_F(GnssSimulation, RinexObservationsAreTheSimulatedOnes) {
  const auto obs = visors::gnss::files::read_rinex3_observations(*dir_ / "dsc.rnx");
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  EXPECT_EQ(obs->header.marker_name, "DSC");
  ASSERT_EQ(obs->epochs.size(), 121u);
  std::istringstream truth(read(*dir_ / "channels_truth.csv"));
  std::string row;
  std::getline(truth, row);  // header
  std::map<std::pair<long, int>, std::vector<double>> expected;  // (t, prn) -> truth row
  while (std::getline(truth, row)) {
    std::stringstream fields(row);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(fields, cell, ',')) cells.push_back(cell);
    if (cells[1] != "dsc") continue;
    std::vector<double> values;
    for (std::size_t k = 3; k < cells.size(); ++k) values.push_back(std::stod(cells[k]));
    expected[{std::lround(std::stod(cells[0])), std::stoi(cells[2])}] = values;
  }
  std::map<long, double> receiver_clock_m;  // truth.csv: t_s, spacecraft, ..., receiver_clock_m (12th)
  std::istringstream truth_rows(read(*dir_ / "truth.csv"));
  std::getline(truth_rows, row);
  while (std::getline(truth_rows, row)) {
    std::stringstream fields(row);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(fields, cell, ',')) cells.push_back(cell);
    if (cells[1] == "dsc") receiver_clock_m[std::lround(std::stod(cells[0]))] = std::stod(cells[11]);
  }
  const double lambda = visors::gnss::kL1WavelengthM;
  std::size_t checked = 0;
  for (std::size_t k = 0; k < obs->epochs.size(); ++k) {
    const auto& epoch = obs->epochs[k];
    EXPECT_FALSE(epoch.receiver_clock_offset_s.has_value());
    const double clock_m = receiver_clock_m.at(static_cast<long>(k));
    for (const auto& sat : epoch.satellites) {
      const auto it = expected.find({static_cast<long>(k), sat.prn});
      ASSERT_NE(it, expected.end()) << "epoch " << k << " G" << sat.prn;
      // range, satellite clock, ionosphere, ambiguity, satellite phase, receiver phase, elevation
      const auto& t = it->second;
      const double geometry = t[0] + clock_m - t[1];
      EXPECT_NEAR(*sat.values[0].value, geometry + t[2], 1.0);
      EXPECT_NEAR(lambda * *sat.values[1].value, geometry - t[2] + lambda * (t[3] + t[5] - t[4]), 0.0102);
      ++checked;
    }
  }
  EXPECT_EQ(checked, expected.size());
}

}  // namespace
