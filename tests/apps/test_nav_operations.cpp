// `visors nav` on a run with the campaign's operations: a 10-minute `visors gnss-sim` run of the
// default scenario with maneuvers of the OSC, an observation with its slews and the laser
// rangefinder, replayed through both filters; and the same operations with the phase degraded so
// that no fix is possible, where the laser ranges must carry the line of sight.
#include <gtest/gtest.h>

#include <cmath>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "visors/core/files/data_path.hpp"
#include "gnss/gnss_test_data.hpp"
#include "run_tool.hpp"
#include "support/csv_table.hpp"
#include "support/temp_file.hpp"
#include "support/white_receiver.hpp"

namespace visors::test {
namespace {

bool have_navigation_file() { return have_gnss_data("NYA100NOR_S_20241280000_01D_GN.rnx"); }

// The default gnss-sim scenario, 600 s, with an observation at 300-360 s (slews from 150 s and
// back until ~510 s), OSC maneuver pieces from 60 s (three before the slew; the rest of the
// burst falls in it and is skipped), laser ranges every 2 s in the observation.
std::string operations_scenario(const std::filesystem::path& dir, const std::string& name, double phase_sigma_m) {
  std::string text = file_text(std::filesystem::path(VISORS_SOURCE_DIR) / "data/scenarios/gnss_sim.toml");
  replace_once(text, "duration_s = 5700.0", "duration_s = 600.0");
  replace_once(text, "attitude = \"nominal\"", "attitude = \"campaign\"");
  replace_once(text, "phase_sigma_m = 0.002", "phase_sigma_m = " + std::to_string(phase_sigma_m));
  replace_once(text, "first_start_s = 1500.0", "first_start_s = 300.0");
  replace_once(text, "duration_s = 10.0", "duration_s = 60.0");
  replace_once(text, "spacecraft = \"none\"", "spacecraft = \"osc\"");
  replace_once(text, "first_burst_s = 900.0", "first_burst_s = 60.0");
  replace_once(text, "enabled = false", "enabled = true");
  whiten_shipped_receiver(text);  // the filter's figures under white receiver noise
  // The flight team's filter is told its receiver's noise ([nav]; the filter never reads the
  // truth's): the SD phase of two receivers, sqrt(2) x phase_sigma_m.
  // The slews to and from the observation turn the antenna's phase-centre error about body Y: the
  // filter estimates the boresight component they expose (held at the calibration, its 5 mm error
  // swings the antennas through every slew: 7 mm RMS in the forecast instead of < 3 mm).
  text += "\n[nav]\nsdcp_sigma_m = " + std::to_string(std::sqrt(2.0) * phase_sigma_m) +
          "\nelevation_weighting = false\nphase_center_boresight_estimated = true\n";
  const auto path = dir / (name + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

nlohmann::json replay(const std::filesystem::path& run, const std::filesystem::path& out, const std::string& options) {
  const auto nav = run_visors("nav " + run.string() + " --out " + out.string() + " " + options);
  EXPECT_EQ(nav.exit_code, 0) << nav.err;
  return nav.exit_code == 0 ? nlohmann::json::parse(file_text(out / "summary.json")) : nlohmann::json{};
}

class NavOperations : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!have_navigation_file()) return;
    dir = new TempDir();
    const auto run = dir->path() / "run";
    const auto sim = run_visors("gnss-sim " + operations_scenario(dir->path(), "ops", 0.002) + " --out " + run.string());
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    nominal = replay(run, dir->path() / "nav", "");
    delayed = replay(run, dir->path() / "delayed", "--crosslink-delay 2.5");
    // 5 cm phase: the float filter alone, with and without the laser ranges.
    const auto degraded = dir->path() / "degraded";
    const auto sim2 = run_visors("gnss-sim " + operations_scenario(dir->path(), "degraded", 0.05) + " --out " + degraded.string());
    ASSERT_EQ(sim2.exit_code, 0) << sim2.err;
    with_laser = replay(degraded, dir->path() / "with_laser", "--float");
    without_laser = replay(degraded, dir->path() / "without_laser", "--float --no-laser");
  }
  static void TearDownTestSuite() { delete dir; }
  void SetUp() override {
    if (!have_navigation_file()) GTEST_FAIL() << "a data file of data/ not found in data/ nor VISORS_DATA_PATH (data/SOURCES.md)";
    ASSERT_FALSE(nominal.is_null());
    ASSERT_FALSE(delayed.is_null());
    ASSERT_FALSE(with_laser.is_null());
    ASSERT_FALSE(without_laser.is_null());
  }
  static int rows(const std::filesystem::path& csv) {
    std::istringstream in(file_text(csv));
    int n = -1;  // the header
    for (std::string line; std::getline(in, line);) ++n;
    return n;
  }
  static TempDir* dir;
  static nlohmann::json nominal, delayed, with_laser, without_laser;
};
TempDir* NavOperations::dir = nullptr;
nlohmann::json NavOperations::nominal;
nlohmann::json NavOperations::delayed;
nlohmann::json NavOperations::with_laser;
nlohmann::json NavOperations::without_laser;

// Every commanded impulse of the run (maneuvers.csv; all after the cold start) reaches both
// filters: the local one's own command, the remote's over the crosslink.
TEST_F(NavOperations, AppliesEveryCommandedImpulse) {
  const int pieces = rows(dir->path() / "run" / "maneuvers.csv");
  ASSERT_GT(pieces, 0);
  for (int k = 0; k < 2; ++k) EXPECT_EQ(nominal["filters"][k]["impulses_applied"].get<int>(), pieces) << k;
}

// Fix rate >= 99.5 % after the first fix (docs/requirements.md#navigation-acceptance-figures),
// through the maneuvers and the slews.
TEST_F(NavOperations, StaysFixedThroughManeuversAndSlews) {
  for (int k = 0; k < 2; ++k) EXPECT_GE(nominal["filters"][k]["after_first_fix"]["fix_rate"].get<double>(), 0.995) << k;
}

TEST_F(NavOperations, NoWrongFix) {
  for (int k = 0; k < 2; ++k) EXPECT_EQ(nominal["filters"][k]["after_first_fix"]["wrong_fix_epochs"].get<int>(), 0) << k;
}

// Worst epoch <= 1 cm outside slews (the antennas: what GPS sees;
// docs/requirements.md#navigation-acceptance-figures).
TEST_F(NavOperations, WorstEpochOutsideSlewsBelowACentimetre) {
  for (int k = 0; k < 2; ++k) {
    EXPECT_LT(nominal["filters"][k]["after_first_fix"]["relative_antenna_worst_outside_slews_m"].get<double>(), 0.01) << k;
  }
}

// The observation's 31 ranges (every 2 s over 60 s, ends included) are all used by the OSC's
// filter, none rejected: the fixed solution agrees with them.
TEST_F(NavOperations, UsesEveryLaserRange) {
  const auto& o = nominal["filters"][1]["observations"];
  EXPECT_EQ(o["laser_ranges_used"].get<int>(), rows(dir->path() / "run" / "lrf.csv"));
  EXPECT_EQ(o["laser_ranges_rejected"].get<int>(), 0);
}

// With the DD phase degraded so that no fix is possible, the laser fusion visibly cuts the
// line-of-sight error of the payload points during the observation (here: at least halves;
// docs/requirements.md#navigation-acceptance-figures).
TEST_F(NavOperations, LaserCutsTheLineOfSightErrorWithoutAFix) {
  for (int k = 0; k < 2; ++k) {
    const double with = with_laser["filters"][k]["observations"]["payload_los_rms_m"].get<double>();
    const double without = without_laser["filters"][k]["observations"]["payload_los_rms_m"].get<double>();
    EXPECT_LT(with, 0.5 * without) << k << ": " << without << " -> " << with;
  }
}

// A 2.5 s crosslink delay: each joint epoch's solution is in use 3 s later (whole epochs),
// carried there by the forecast with the commanded impulses of those seconds; the antennas stay
// millimetric (relative position <= 3 mm: docs/requirements.md#navigation-acceptance-figures).
TEST_F(NavOperations, CrosslinkDelayKeepsTheSolutionMillimetricWhenInUse) {
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(delayed["filters"][k]["latency_s"].get<double>(), 3.0) << k;
    EXPECT_LT(delayed["filters"][k]["converged"]["forecast_antenna_rms_m"].get<double>(), 0.003) << k;
  }
}

TEST_F(NavOperations, FloatReplayNeverFixes) {
  for (int k = 0; k < 2; ++k) EXPECT_EQ(with_laser["filters"][k]["time_to_first_fix_s"].get<double>(), -1.0) << k;
}

TEST(NavCommand, SettingsFileWithAnUnknownKeyNamesIt) {
  TempDir dir;
  std::ofstream(dir.path() / "nav.toml") << "[nav]\nsdcp_sigma = 0.004\n";
  const auto run = run_visors("nav /tmp/visors-no-such-run --settings " + (dir.path() / "nav.toml").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("nav.sdcp_sigma"), std::string::npos) << run.err;
}

TEST(NavCommand, CrosslinkDelayAboveAMinuteNamesTheOption) {
  const auto run = run_visors("nav /tmp/visors-no-such-run --crosslink-delay 100");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--crosslink-delay"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace visors::test
